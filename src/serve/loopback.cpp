#include "loopback.h"

#include <cctype>
#include <string>

namespace modsynth::app {
namespace {

bool equals_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

bool is_decimal(std::string_view text, unsigned max) {
    if (text.empty() || text.size() > 5) return false;
    unsigned v = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return false;
        v = v * 10 + static_cast<unsigned>(c - '0');
    }
    return v <= max;
}

bool is_loopback_ipv4(std::string_view host) {
    int parts = 0;
    for (;;) {
        const auto dot = host.find('.');
        const auto part = host.substr(0, dot);
        if (part.size() > 3 || !is_decimal(part, 255)) return false;
        if (parts == 0 && part != "127") return false;
        ++parts;
        if (dot == std::string_view::npos) break;
        host.remove_prefix(dot + 1);
    }
    return parts == 4;
}

}  // namespace

bool is_loopback_host(std::string_view host) {
    return equals_ignoring_case(host, "localhost") || host == "::1" || host == "[::1]" ||
           is_loopback_ipv4(host);
}

bool is_loopback_host_header(std::string_view value, int port) {
    std::string_view host = value, port_text;
    if (!value.empty() && value.front() == '[') {
        const auto close = value.find(']');
        if (close == std::string_view::npos) return false;
        host = value.substr(0, close + 1);
        const auto rest = value.substr(close + 1);
        if (!rest.empty()) {
            if (rest.front() != ':') return false;
            port_text = rest.substr(1);
            if (port_text.empty()) return false;
        }
        if (host != "[::1]") return false;
    } else {
        const auto colon = value.find(':');
        if (colon != std::string_view::npos) {
            host = value.substr(0, colon);
            port_text = value.substr(colon + 1);
            if (port_text.empty()) return false;
        }
        if (host == "::1" || !is_loopback_host(host)) return false;
    }
    return port_text.empty() ||
           (is_decimal(port_text, 65535) && std::stoi(std::string(port_text)) == port);
}

}  // namespace modsynth::app
