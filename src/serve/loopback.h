#pragma once
// Which names and addresses mean this machine's loopback. The server
// listens there by default and answers only requests addressed there, so
// that a page from elsewhere cannot reach it through a DNS name rebound to
// 127.0.0.1: the browser still sends that name as the Host.
#include <string_view>

namespace modsynth::app {

/// True for "localhost", "::1" (bracketed or not) and the dotted IPv4
/// literals 127.X.Y.Z (each part a decimal number up to 255); nothing else,
/// so "127.attacker.example" is not one.
bool is_loopback_host(std::string_view host);

/// True when a Host header names the loopback, without a port or with
/// `port` (the one the request came in on).
bool is_loopback_host_header(std::string_view value, int port);

}  // namespace modsynth::app
