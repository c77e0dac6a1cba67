#include "loopback.h"

#include <catch2/catch.hpp>

using modsynth::app::is_loopback_host;
using modsynth::app::is_loopback_host_header;

TEST_CASE("loopback hosts are the loopback literals and localhost, nothing that starts like one") {
    for (const char* host : {"localhost", "LocalHost", "::1", "[::1]", "127.0.0.1", "127.255.1.0"})
        CHECK(is_loopback_host(host));
    for (const char* host : {"127.attacker.example", "127.0.0.1.attacker.example", "127.0.0.256",
                             "127.0.0", "127.0.0.1.", "127..0.1", "1270.0.0.1", "127.0.0.-1",
                             "localhost.attacker.example", "0.0.0.0", "::2", "", "128.0.0.1"})
        CHECK_FALSE(is_loopback_host(host));
}

TEST_CASE("a Host header names the loopback with the server's port or none") {
    CHECK(is_loopback_host_header("127.0.0.1", 8080));
    CHECK(is_loopback_host_header("127.0.0.1:8080", 8080));
    CHECK(is_loopback_host_header("localhost:8080", 8080));
    CHECK(is_loopback_host_header("[::1]:8080", 8080));
    CHECK(is_loopback_host_header("[::1]", 8080));
    CHECK_FALSE(is_loopback_host_header("127.0.0.1:8081", 8080));
    CHECK_FALSE(is_loopback_host_header("127.0.0.1:", 8080));
    CHECK_FALSE(is_loopback_host_header("127.0.0.1:80x", 8080));
    CHECK_FALSE(is_loopback_host_header("::1", 8080));  // unbracketed: not a Host
    CHECK_FALSE(is_loopback_host_header("[::1]x", 8080));
    CHECK_FALSE(is_loopback_host_header("[::1", 8080));
    CHECK_FALSE(is_loopback_host_header("127.attacker.example:8080", 8080));
    CHECK_FALSE(is_loopback_host_header("localhost:8080:8080", 8080));
}
