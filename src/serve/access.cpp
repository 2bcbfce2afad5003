#include "nck/serve/access.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <random>

#include <fmt/format.h>

namespace nck::app::serve {

std::string make_token() {
  std::random_device rd;  // /dev/urandom on Linux
  std::string token;
  for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", static_cast<std::uint32_t>(rd()));
  return token;
}

bool same_token(std::string_view a, std::string_view b) noexcept {
  // Every byte of the expected token is looked at, whatever the other one is.
  unsigned diff = a.size() == b.size() ? 0u : 1u;
  for (std::size_t i = 0; i < b.size(); ++i) diff |= static_cast<unsigned char>(b[i]) ^ static_cast<unsigned char>(i < a.size() ? a[i] : 0);
  return diff == 0 && !b.empty();
}

namespace {

std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// The value of `name` in "k1=v1<sep>k2=v2...".
std::string_view pair_value(std::string_view list, char sep, std::string_view name) noexcept {
  while (!list.empty()) {
    const std::size_t end = list.find(sep);
    const std::string_view pair = trim(list.substr(0, end));
    list = end == std::string_view::npos ? std::string_view{} : list.substr(end + 1);
    const std::size_t eq = pair.find('=');
    if (eq != std::string_view::npos && pair.substr(0, eq) == name) return pair.substr(eq + 1);
  }
  return {};
}

}  // namespace

std::string_view cookie_value(std::string_view cookie_header, std::string_view name) noexcept {
  return pair_value(cookie_header, ';', name);
}

std::string_view bearer_token(std::string_view authorization) noexcept {
  // The scheme is case-insensitive (RFC 9110, 11.1): "bearer" too.
  constexpr std::string_view kBearer = "bearer ";
  if (authorization.size() < kBearer.size()) return {};
  for (std::size_t i = 0; i < kBearer.size(); ++i)
    if ((authorization[i] | 0x20) != kBearer[i]) return {};  // ' ' | 0x20 is ' '
  return trim(authorization.substr(kBearer.size()));
}

std::string_view query_value(std::string_view target, std::string_view name) noexcept {
  const std::size_t q = target.find('?');
  return q == std::string_view::npos ? std::string_view{} : pair_value(target.substr(q + 1), '&', name);
}

ServerNames::ServerNames(std::string bind_address, std::uint16_t port) {
  const bool v6 = bind_address.find(':') != std::string::npos;
  for (const std::string& h : {std::string("127.0.0.1"), std::string("localhost"), v6 ? "[" + bind_address + "]" : bind_address})
    hosts_.push_back(fmt::format("{}:{}", h, port));
}

bool ServerNames::host_ok(std::string_view host) const noexcept {
  return std::find(hosts_.begin(), hosts_.end(), host) != hosts_.end();
}

bool ServerNames::origin_ok(std::string_view origin) const noexcept {
  constexpr std::string_view kScheme = "http://";
  return origin.starts_with(kScheme) && host_ok(origin.substr(kScheme.size()));
}

bool RequestBudget::take(std::chrono::steady_clock::time_point now) noexcept {
  if (last_ != std::chrono::steady_clock::time_point{}) {
    const double dt_s = std::chrono::duration<double>(now - last_).count();
    tokens_ = std::min(rate_per_s_, tokens_ + dt_s * rate_per_s_);
  }
  last_ = now;
  if (tokens_ < 1.0) return false;
  tokens_ -= 1.0;
  return true;
}

bool loopback(const std::string& address) {
  return address == "127.0.0.1" || address == "::1" || address.starts_with("127.");
}

std::optional<std::string> read_token(const std::string& token_file, const std::string& bind, std::string& why) {
  if (token_file.empty()) {
    if (!loopback(bind)) {
      why = fmt::format("--bind {} reaches beyond this machine: give --token-file FILE with a secret of at least "
                        "32 characters", bind);
      return std::nullopt;
    }
    return make_token();
  }
  std::ifstream in(token_file);
  std::string token;
  std::getline(in, token);
  while (!token.empty() && (token.back() == '\r' || token.back() == ' ')) token.pop_back();
  const bool printable = std::all_of(token.begin(), token.end(), [](char c) { return c > ' ' && c < 127 && c != ';'; });
  if (!in.good() && token.empty()) why = fmt::format("--token-file {} cannot be read", token_file);
  else if (token.size() < 32 || !printable)
    why = "the token in --token-file must be at least 32 printable characters (128 bits), without spaces or ';'";
  if (!why.empty()) return std::nullopt;
  return token;
}

}  // namespace nck::app::serve
