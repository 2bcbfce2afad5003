#pragma once
// nck serve's HTTP side (Boost.Beast over Asio, one thread): it serves at
// most `max_clients` connections with the token (and `max_anonymous`
// without one yet, the oldest making room), checks Host and Origin on every
// request, the token on everything under /api/ (before a body is read), a
// request budget per connection and the body size, and hands what passes
// to an ApiHandler. GET /api/v1/stream
// turns a connection into a server-sent-events stream that gets, every
// `stream_period`, the frames the handler collects. Nothing a client sends
// reaches the kernel but through the handler.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "nck/core/diagnostic.hpp"

namespace nck::app::serve {

struct HttpLimits {
  std::size_t max_clients = 8;           // connections with the token; one more request with it: 503
  std::size_t max_anonymous_per_address = 4;  // connections without a token yet, per address (the oldest goes)
  std::size_t max_anonymous = 64;        // connections without a token yet, in all (the oldest goes)
  std::chrono::milliseconds header_timeout{5000};  // a connection's complete request, until one had the token
  double requests_per_s = 50;            // per connection; beyond: 429
  std::size_t max_command_bytes = 64 * 1024;
  std::size_t max_upload_bytes = 4 * 1024 * 1024;  // POST /api/v1/upload
  std::size_t max_stream_backlog = 64;   // frames a slow stream client may owe before it is dropped
  std::chrono::milliseconds stream_period{25};  // 40 snapshots per second
  std::size_t largest_body() const { return std::max(max_command_bytes, max_upload_bytes); }
};

struct HttpRequest {
  std::string_view method;  // "GET", "POST"
  std::string_view target;  // path and query
  std::string_view body;
};

struct HttpReply {
  unsigned status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;  // extra ones (Set-Cookie, Location)
};

// A refusal: {"error": DIAGNOSTIC} with its status, the diagnostic's one
// shape (output/diagnostic_json.hpp; docs/api.md).
// `channel`: the channel (1-based) it concerns, 0: none.
HttpReply error_reply(unsigned status, const Diagnostic& d, std::size_t channel = 0);
HttpReply error_reply(unsigned status, ErrorId id, std::string message);

class ApiHandler {
 public:
  virtual ~ApiHandler() = default;
  // A request that passed the checks (under /api/: with a valid token).
  virtual HttpReply handle(const HttpRequest& r) = 0;
  // Every stream period: the frames ("event: ...\ndata: ...\n\n") for every stream client.
  virtual void collect(std::vector<std::string>& frames) = 0;
  // The frames a new stream client gets first (the whole state); a client
  // that reconnects with Last-Event-ID also gets the events it missed.
  virtual std::string stream_start(std::optional<std::uint64_t> last_event_id) = 0;
};

class HttpServer {
 public:
  // Binds at once (throws std::system_error when it cannot); port 0 takes a free one.
  HttpServer(ApiHandler& handler, const std::string& bind_address, std::uint16_t port, std::string token,
             HttpLimits limits);
  ~HttpServer();
  std::uint16_t port() const;
  // Serves until `stop` is set (looked at every stream period).
  void run(const std::atomic<bool>& stop);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace nck::app::serve
