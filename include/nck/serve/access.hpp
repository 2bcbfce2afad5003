#pragma once
// Who may talk to nck serve: the token printed at start (or read from
// --token-file), compared in constant time; the Host and Origin headers
// that name the server itself (DNS rebinding and other sites' pages are
// refused); a per-client request budget.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace nck::app::serve {

// 128 random bits as 32 hexadecimal digits (the kernel's random source).
std::string make_token();
// An address of this machine only (127.0.0.0/8, ::1).
bool loopback(const std::string& address);
// The token a server started with: `token_file`'s first line (at least
// 128 bits: 32 printable characters), or without a file a fresh random one
// (loopback only: beyond it the secret must be chosen). Why not in `why`.
std::optional<std::string> read_token(const std::string& token_file, const std::string& bind, std::string& why);
// a == b, in a time that does not depend on where they differ.
bool same_token(std::string_view a, std::string_view b) noexcept;
// The value of cookie `name` in a Cookie header, or "".
std::string_view cookie_value(std::string_view cookie_header, std::string_view name) noexcept;
// The token of "Authorization: Bearer TOKEN", or "".
std::string_view bearer_token(std::string_view authorization) noexcept;
// The value of query parameter `name` in a request target ("/x?a=1&b=2"), or "".
std::string_view query_value(std::string_view target, std::string_view name) noexcept;

// The names the server answers to: 127.0.0.1:PORT, localhost:PORT and the
// bound address (IPv6 in brackets).
class ServerNames {
 public:
  ServerNames(std::string bind_address, std::uint16_t port);
  bool host_ok(std::string_view host) const noexcept;
  // An Origin header, when the browser sends one, must be this server's.
  bool origin_ok(std::string_view origin) const noexcept;

 private:
  std::vector<std::string> hosts_;
};

// A token bucket: `rate_per_s` requests per second, as many in a burst.
class RequestBudget {
 public:
  explicit RequestBudget(double rate_per_s) : rate_per_s_(rate_per_s), tokens_(rate_per_s) {}
  bool take(std::chrono::steady_clock::time_point now) noexcept;

 private:
  double rate_per_s_;
  double tokens_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace nck::app::serve
