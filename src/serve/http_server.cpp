#include "nck/serve/http_server.hpp"

#include <charconv>
#include <deque>
#include <map>
#include <optional>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "nck/core/diagnostic.hpp"
#include "nck/output/diagnostic_json.hpp"
#include "nck/serve/access.hpp"

namespace nck::app::serve {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

constexpr std::size_t kMaxHeaderBytes = 8 * 1024;
constexpr auto kIdleTimeout = std::chrono::seconds(60);
constexpr auto kWriteTimeout = std::chrono::seconds(10);
// After a refusal sent before the body was read, the body still coming is
// read and dropped for this long: a close with unread data resets the
// connection, and the client would lose the answer while still sending.
constexpr auto kDrainTimeout = std::chrono::seconds(2);
// A connection younger than this is not evicted: a browser opens several
// at once, and each is without a token until its request has been read.
constexpr auto kEvictionGrace = std::chrono::milliseconds(250);
// A connection without the token that has sent nothing for this long is
// the first to make room: a client sends its request as soon as it is
// connected (the operator's may be accepted a moment before its bytes come).
constexpr auto kSilentGrace = std::chrono::milliseconds(10);
// A stream's socket buffer. Left to the kernel it grew to 4 MB for a client
// that reads nothing (tcp_wmem): the backlog bound (max_stream_backlog) only
// counts once the socket is full, and that took minutes at 40 frames/s. 64 KiB
// holds about two seconds of frames, more than a reader on any link needs.
constexpr int kStreamSendBuffer = 64 * 1024;

}  // namespace

HttpReply error_reply(unsigned status, const Diagnostic& d, std::size_t channel) {
  // the diagnostic's one shape (id, message and remedy among its fields)
  const nlohmann::ordered_json j = {{"error", app::diagnostic_json(d, channel)}};
  // replace, not throw: a message may quote bytes a client sent
  return HttpReply{status, "application/json", j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace), {}};
}

HttpReply error_reply(unsigned status, ErrorId id, std::string message) {
  return error_reply(status, make_diagnostic(id, SourceLoc{}, std::move(message)));
}

struct HttpServer::Impl {
  class Connection;

  ApiHandler& handler;
  std::string token;
  HttpLimits limits;
  asio::io_context io{1};
  tcp::acceptor acceptor{io};
  std::optional<ServerNames> names;
  std::vector<std::weak_ptr<Connection>> streams;
  std::size_t clients = 0;      // connections a request with the token came on (bound: max_clients)
  std::size_t strangers = 0;    // connections without the token yet (bound: max_anonymous)
  std::deque<std::weak_ptr<Connection>> arrivals;  // oldest first: whom to evict
  std::map<std::string, std::size_t> anonymous;  // per address: connections without a valid token yet
  asio::steady_timer tick{io};
  const std::atomic<bool>* stop = nullptr;

  Impl(ApiHandler& h, std::string t, HttpLimits l) : handler(h), token(std::move(t)), limits(l) {}
  void accept();
  void admit(const std::shared_ptr<Connection>& c);
  // Closes the oldest connection without a token for which may_go(it) holds; false when there is none.
  template <class Pred>
  bool evict_oldest(const std::shared_ptr<Connection>& newcomer, ErrorId why, const Pred& may_go);
  void on_tick();
  // The checks every request passes; a refusal, or nothing when it may go on.
  std::optional<HttpReply> check(const http::request<http::string_body>& req, RequestBudget& budget) const;
  bool authorized(const http::request<http::string_body>& req) const;
  // The request carries this server's token (header, cookie or the page's URL).
  bool has_token(const http::request<http::string_body>& req) const;
};

// One client connection: requests one after the other, or a stream.
class HttpServer::Impl::Connection : public std::enable_shared_from_this<Connection> {
 public:
  Connection(Impl& server, tcp::socket socket)
      : server_(server), stream_(std::move(socket)), budget_(server.limits.requests_per_s) {
    beast::error_code ec;
    address_ = stream_.socket().remote_endpoint(ec).address().to_string();
    ++server_.strangers;
    ++server_.anonymous[address_];
  }
  ~Connection() { leave(); }

  void start() { read_header(); }
  const std::string& address() const { return address_; }
  bool anonymous() const { return !authenticated_ && counted_; }
  bool young(std::chrono::steady_clock::time_point now) const { return now - born_ < kEvictionGrace; }
  std::chrono::steady_clock::time_point born() const { return born_; }
  // No byte of a request has come: none parsed or buffered, none waiting in the socket.
  bool silent() {
    beast::error_code ec;
    return buffer_.size() == 0 && !(parser_ && parser_->got_some()) && stream_.socket().available(ec) == 0;
  }
  // Closed to make room for a newer connection: it brought no token in its
  // time. It gets the reason unless it is sending an answer.
  void evict(ErrorId why) {
    evicted_ = true;
    leave();
    if (writing_) return close();
    reply(error_reply(503, why, why == ErrorId::ApiTooManyFromAddress
                                    ? "this address holds too many connections without the token: the oldest goes"
                                    : "too many connections without the token: the oldest goes"),
          After::close);
  }
  // A stream frame (shared by every stream client); drops a client that lags.
  void send(const std::shared_ptr<const std::string>& frame) {
    if (outbox_.size() >= server_.limits.max_stream_backlog) return close();
    outbox_.push_back(frame);
    if (outbox_.size() == 1) write_next();
  }
  void close() {
    beast::error_code ec;
    stream_.socket().shutdown(tcp::socket::shutdown_both, ec);
    stream_.close();
  }

 private:
  // What follows an answer: the next request, the end, or the end after
  // the unread body (drain).
  enum class After : std::uint8_t { next_request, close, drain_and_close };

  void read_header() {
    parser_.emplace();
    parser_->header_limit(kMaxHeaderBytes);
    // Beast checks a Content-Length against the body limit while it reads
    // the header: its default (1 MiB) dropped larger uploads before
    // on_header could raise it. The request's own limit is set there.
    parser_->body_limit(server_.limits.largest_body());
    stream_.expires_after(kIdleTimeout);
    if (!authenticated_) watch_header_time();
    http::async_read_header(stream_, buffer_, *parser_,
                            [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_header(ec); });
  }
  // Until a request brought the token, a connection that sends nothing
  // holds a slot only the header timeout (seven silent sockets locked the
  // operator out for 60 s). A timer of its own, not the stream's timeout:
  // that one closes the socket, and the 408 would not get out.
  void watch_header_time() {
    header_timer_.expires_after(server_.limits.header_timeout);
    header_timer_.async_wait([weak = weak_from_this()](beast::error_code ec) {
      const auto self = weak.lock();
      if (ec || !self) return;
      self->header_late_ = true;
      beast::error_code ignored;
      self->stream_.socket().cancel(ignored);  // the read ends with operation_aborted
    });
  }
  void on_header(beast::error_code ec) {
    if (evicted_) return;  // the 503 is the answer (and its write closes the connection)
    if (header_late_) return request_timeout();
    if (ec == http::error::header_limit)
      return reply(error_reply(431, ErrorId::ApiHeadersTooLarge,
                               fmt::format("the headers are larger than {} bytes", kMaxHeaderBytes)),
                   After::drain_and_close);
    if (ec == http::error::body_limit || ec == http::error::bad_content_length) return too_large();
    if (ec) return close();
    const http::request<http::string_body>& req = parser_->get();
    const bool upload = req.target().starts_with("/api/v1/upload");
    const std::size_t limit = upload ? server_.limits.max_upload_bytes : server_.limits.max_command_bytes;
    if (const auto length = parser_->content_length(); length && *length > limit) return too_large();
    // The header decides. A connection without the token is refused before
    // the body is read, so it never holds one (up to --max-program); a
    // client's refusal (429) waits for the body, and its connection stays.
    refusal_ = admit_request(req);
    if (refusal_ && !authenticated_) return reply(*refusal_, parser_->is_done() ? after(req) : After::drain_and_close);
    parser_->body_limit(limit);  // a chunked body is counted as it comes
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code e, std::size_t) { self->on_request(e); });
  }
  void too_large() {
    reply(error_reply(413, ErrorId::ApiTooLarge, "the body is larger than this request accepts (docs/api.md)"),
          After::drain_and_close);
  }
  void request_timeout() {
    reply(error_reply(408, ErrorId::ApiRequestTimeout, "no complete request with the token in time"), After::close);
  }
  void on_request(beast::error_code ec) {
    header_timer_.cancel();  // the whole request came (or failed) in time
    // Evicted while its request was still coming: it ran all the same, and
    // its answer was a second write beside the 503 (issue 45's attack campaign).
    if (evicted_) return;
    if (header_late_) return request_timeout();
    if (ec == http::error::body_limit) return too_large();
    if (ec) return close();
    const http::request<http::string_body>& req = parser_->get();
    if (refusal_) return reply(*refusal_, after(req));
    if (req.method() == http::verb::get && req.target() == "/api/v1/stream") return start_stream(last_event_id(req));
    const HttpRequest r{std::string_view(req.method_string().data(), req.method_string().size()),
                        std::string_view(req.target().data(), req.target().size()),
                        std::string_view(req.body().data(), req.body().size())};
    reply(server_.handler.handle(r), after(req));
  }
  static After after(const http::request<http::string_body>& req) {
    return req.keep_alive() ? After::next_request : After::close;
  }
  // A request with the token makes its connection a client (past
  // max_clients: 503); then the checks every request passes.
  std::optional<HttpReply> admit_request(const http::request<http::string_body>& req) {
    if (!authenticated_ && counted_ && server_.has_token(req)) {
      if (server_.clients >= server_.limits.max_clients)
        return error_reply(503, ErrorId::ApiTooManyClients,
                           fmt::format("{} clients with the token are connected", server_.clients));
      forget_anonymous();
      authenticated_ = true;
      ++server_.clients;
    }
    return server_.check(req, budget_);
  }
  void reply(const HttpReply& r, After after) {
    auto res = std::make_shared<http::response<http::string_body>>(static_cast<http::status>(r.status), 11);
    res->set(http::field::content_type, r.content_type);
    res->set(http::field::cache_control, "no-store");
    res->set("Referrer-Policy", "no-referrer");
    res->set("X-Content-Type-Options", "nosniff");
    for (const auto& [k, v] : r.headers) res->set(k, v);
    res->body() = r.body;
    res->keep_alive(after == After::next_request);
    res->prepare_payload();
    stream_.expires_after(kWriteTimeout);
    writing_ = true;
    http::async_write(stream_, *res, [self = shared_from_this(), res, after](beast::error_code ec, std::size_t) {
      self->writing_ = false;
      if (ec || after == After::close) return self->close();
      if (after == After::drain_and_close) return self->drain();
      self->read_header();
    });
  }
  // The answer is out: the client's unread body is read and dropped until
  // it closes or kDrainTimeout ends.
  void drain() {
    beast::error_code ec;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ec);
    stream_.expires_after(kDrainTimeout);
    drain_some();
  }
  void drain_some() {
    stream_.async_read_some(asio::buffer(sink_), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->close();
      self->drain_some();
    });
  }
  // The connection becomes a server-sent-events stream until either side closes it.
  // The Last-Event-ID header of a reconnecting stream client (none when absent or not a number).
  static std::optional<std::uint64_t> last_event_id(const http::request<http::string_body>& req) {
    const auto it = req.find("Last-Event-ID");
    if (it == req.end()) return std::nullopt;
    std::uint64_t id = 0;
    const auto v = it->value();
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), id);
    return ec == std::errc{} && end == v.data() + v.size() ? std::optional(id) : std::nullopt;
  }
  void start_stream(std::optional<std::uint64_t> last_id) {
    beast::error_code ec;
    stream_.socket().set_option(asio::socket_base::send_buffer_size(kStreamSendBuffer), ec);
    server_.streams.push_back(weak_from_this());
    std::string head =
        "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\n"
        "Referrer-Policy: no-referrer\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n\r\n";
    send(std::make_shared<const std::string>(std::move(head) + server_.handler.stream_start(last_id)));
    watch_for_close();
  }
  // A stream client sends nothing more: a read ends only when it goes away.
  void watch_for_close() {
    stream_.expires_never();
    stream_.socket().async_read_some(asio::buffer(sink_), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->close();
      self->watch_for_close();
    });
  }
  void write_next() {
    stream_.expires_after(kWriteTimeout);
    asio::async_write(stream_.socket(), asio::buffer(*outbox_.front()),
                      [self = shared_from_this()](beast::error_code ec, std::size_t) {
                        if (ec) return self->close();
                        self->outbox_.pop_front();
                        if (!self->outbox_.empty()) self->write_next();
                      });
  }

  // The server's counts without this connection (once).
  void leave() {
    if (!counted_) return;
    if (authenticated_) --server_.clients;
    else forget_anonymous();
    counted_ = false;
  }
  void forget_anonymous() {
    --server_.strangers;
    if (const auto it = server_.anonymous.find(address_); it != server_.anonymous.end() && --it->second == 0)
      server_.anonymous.erase(it);
  }

  Impl& server_;
  std::string address_;
  bool authenticated_ = false;  // a request brought the token
  bool counted_ = true;         // in the server's counts (until evicted or gone)
  bool writing_ = false;        // an answer is on its way
  std::chrono::steady_clock::time_point born_ = std::chrono::steady_clock::now();
  bool header_late_ = false;    // the header timeout ended the read
  bool evicted_ = false;        // made room for a newer connection: nothing it sends counts
  std::optional<HttpReply> refusal_;  // the answer the request's header earned, given after its body
  beast::tcp_stream stream_;
  asio::steady_timer header_timer_{stream_.get_executor()};  // after stream_: made from it
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  RequestBudget budget_;
  std::deque<std::shared_ptr<const std::string>> outbox_;
  std::array<char, 512> sink_{};
};

void HttpServer::Impl::accept() {
  acceptor.async_accept([this](beast::error_code ec, tcp::socket socket) {
    if (!ec) {
      auto c = std::make_shared<Connection>(*this, std::move(socket));
      admit(c);
    }
    if (acceptor.is_open()) accept();
  });
}

// A connection that has brought no token yet yields its place to a newer
// one: silent sockets (held at most the header timeout anyway) never lock
// the operator out. Per address at most max_anonymous_per_address of them:
// the oldest older than kEvictionGrace goes (a browser opens several at
// once). Past max_anonymous in all, one goes whatever its age: the oldest
// that has sent nothing for kSilentGrace, else the oldest. A newcomer never
// waits for a place, and the operator's connection only has to bring its
// request before max_anonymous newer ones came (issue 45's attack campaign:
// in the client bound's 8 places, a flood of new sockets kept every place
// young and the operator got 503 for as long as it lasted).
void HttpServer::Impl::admit(const std::shared_ptr<Connection>& c) {
  std::erase_if(arrivals, [](const std::weak_ptr<Connection>& w) { return w.expired(); });
  arrivals.push_back(c);
  const auto now = std::chrono::steady_clock::now();
  const std::string& from = c->address();
  if (anonymous[from] > limits.max_anonymous_per_address)
    (void)evict_oldest(c, ErrorId::ApiTooManyFromAddress,
                       [&](const Connection& old) { return old.address() == from && !old.young(now); });
  if (strangers > limits.max_anonymous &&
      !evict_oldest(c, ErrorId::ApiTooManyClients,
                    [&](Connection& old) { return now - old.born() > kSilentGrace && old.silent(); }))
    (void)evict_oldest(c, ErrorId::ApiTooManyClients, [](const Connection&) { return true; });
  c->start();
}

template <class Pred>
bool HttpServer::Impl::evict_oldest(const std::shared_ptr<Connection>& newcomer, ErrorId why, const Pred& may_go) {
  for (const std::weak_ptr<Connection>& w : arrivals) {
    const auto old = w.lock();
    if (!old || old == newcomer || !old->anonymous() || !may_go(*old)) continue;
    old->evict(why);
    return true;
  }
  return false;
}

bool HttpServer::Impl::has_token(const http::request<http::string_body>& req) const {
  const std::string_view target(req.target().data(), req.target().size());
  return authorized(req) || same_token(query_value(target, "token"), token);
}

bool HttpServer::Impl::authorized(const http::request<http::string_body>& req) const {
  const auto header = [&](http::field f) {
    const auto it = req.find(f);
    return it == req.end() ? std::string_view{} : std::string_view(it->value().data(), it->value().size());
  };
  std::string_view given = bearer_token(header(http::field::authorization));
  if (given.empty()) given = cookie_value(header(http::field::cookie), "nck_token");
  return same_token(given, token);
}

std::optional<HttpReply> HttpServer::Impl::check(const http::request<http::string_body>& req,
                                                  RequestBudget& budget) const {
  const auto host_it = req.find(http::field::host);
  const std::string_view host = host_it == req.end() ? std::string_view{} : std::string_view(host_it->value().data(), host_it->value().size());
  if (!names->host_ok(host)) return error_reply(403, ErrorId::ApiForbiddenOrigin, "the Host header is not this server's");
  if (const auto o = req.find(http::field::origin); o != req.end()) {
    const std::string_view origin(o->value().data(), o->value().size());
    if (origin != fmt::format("http://{}", host))
      return error_reply(403, ErrorId::ApiForbiddenOrigin, "the Origin header is not this server's");
  }
  if (!budget.take(std::chrono::steady_clock::now()))
    return error_reply(429, ErrorId::ApiRateLimited, fmt::format("more than {} requests per second", limits.requests_per_s));
  const std::string_view target(req.target().data(), req.target().size());
  // The API's description is public, like the page (OpenAPI: "security": []).
  const bool public_api = target == "/api/v1/openapi.json";
  if (target.starts_with("/api/") && !public_api && !authorized(req))
    return error_reply(401, ErrorId::ApiUnauthorized, "no valid token: open the URL nck serve printed");
  // The page's URL token becomes a cookie the scripts cannot read, and leaves the address bar.
  if (const std::string_view t = query_value(target, "token"); !t.empty()) {
    if (!same_token(t, token)) return error_reply(401, ErrorId::ApiUnauthorized, "the token in the URL is not this server's");
    return HttpReply{303, "text/plain", "", {{"Location", "/"},
                                             {"Set-Cookie", fmt::format("nck_token={}; HttpOnly; SameSite=Strict; Path=/", token)}}};
  }
  return std::nullopt;
}

void HttpServer::Impl::on_tick() {
  if (stop->load(std::memory_order_acquire)) {
    beast::error_code ec;
    acceptor.close(ec);
    for (auto& w : streams)
      if (auto c = w.lock()) c->close();
    io.stop();
    return;
  }
  std::vector<std::string> frames;
  handler.collect(frames);
  std::erase_if(streams, [](const std::weak_ptr<Connection>& w) { return w.expired(); });
  for (std::string& f : frames) {
    auto shared = std::make_shared<const std::string>(std::move(f));
    for (auto& w : streams)
      if (auto c = w.lock()) c->send(shared);
  }
  tick.expires_after(limits.stream_period);
  tick.async_wait([this](beast::error_code) { on_tick(); });
}

HttpServer::HttpServer(ApiHandler& handler, const std::string& bind_address, std::uint16_t port, std::string token,
                       HttpLimits limits)
    : impl_(std::make_unique<Impl>(handler, std::move(token), limits)) {
  const tcp::endpoint at(asio::ip::make_address(bind_address), port);
  impl_->acceptor.open(at.protocol());
  impl_->acceptor.set_option(asio::socket_base::reuse_address(true));
  impl_->acceptor.bind(at);
  impl_->acceptor.listen();
  impl_->names.emplace(bind_address, this->port());
}

HttpServer::~HttpServer() = default;

std::uint16_t HttpServer::port() const { return impl_->acceptor.local_endpoint().port(); }

void HttpServer::run(const std::atomic<bool>& stop) {
  impl_->stop = &stop;
  impl_->accept();
  impl_->on_tick();
  impl_->io.run();
}

}  // namespace nck::app::serve
