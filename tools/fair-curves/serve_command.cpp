// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves serve: the curve editor's HTTP server (issue 27; doc/editor_api.md). Boost.Beast
// over one thread per connection (at most max_connections at once), each connection with its own
// io_context so that its reads and writes have deadlines (beast::tcp_stream::expires_after) while
// the thread blocks on a solve. Every cold solve, export and metrics request runs the program
// itself in a child process (serve/child_process.h) on files written to the request's scratch
// directory, so the answer is the program's own output byte for byte; kappa sessions re-solve
// warm in process (serve/kappa_sessions.h). The page is compiled in (serve/static_assets.h).

#include "registry.h"
#include "serve/child_process.h"
#include "serve/kappa_sessions.h"
#include "serve/request.h"
#include "serve/static_assets.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cctype>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = net::ip::tcp;
using namespace fair_curves::serve;

// Caps (doc/editor_api.md, "Caps"; also in `fair-curves serve --help`).
constexpr std::size_t max_body = std::size_t(4) << 20;        ///< request body, bytes
constexpr std::size_t max_head = 8 * 1024;                    ///< request line and headers, bytes
constexpr int max_connections = 32;                           ///< served at once; more get 503
constexpr std::chrono::seconds idle_timeout{10};              ///< to read one request
constexpr std::chrono::seconds write_timeout{30};             ///< to write one answer
constexpr std::chrono::seconds ws_idle_timeout{300};          ///< an open /api/ws without a message

struct Serve_options {
  int port = 8080;
  std::string bind = "127.0.0.1", editor_dir;
  bool open = false;
  double solve_timeout = 20;
};

/// One answer.
struct Answer {
  http::status status = http::status::ok;
  std::string content_type = "application/json", body;
  std::vector<std::pair<std::string, std::string>> headers;
  bool close = false;  ///< close the connection after it (the request was not read to its end)
};

std::string error_json(const std::string& message) {
  return nlohmann::json{{"error", message}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

Answer error_answer(http::status status, const std::string& message) {
  Answer a;
  a.status = status;
  a.body = error_json(message);
  return a;
}

std::string seconds_text(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", s);
  return buffer;
}

std::string signal_name(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGABRT: return "SIGABRT";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGBUS: return "SIGBUS";
    case SIGKILL: return "SIGKILL";
    case SIGXCPU: return "SIGXCPU";
    case SIGTERM: return "SIGTERM";
    default: return "signal " + std::to_string(sig);
  }
}

/// The program's own message from its stderr: without "fair-curves: error: " and CLI11's "Run
/// with --help" line.
std::string program_message(const std::string& err) {
  std::string s = err;
  const std::string prefix = "fair-curves: error: ";
  if (s.rfind(prefix, 0) == 0) s = s.substr(prefix.size());
  const std::size_t help = s.find("Run with --help for more information.");
  if (help != std::string::npos) s = s.substr(0, help);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r')) s.pop_back();
  if (s.empty()) s = "the program refused the data";
  return s;
}

/// A scratch directory of one request (mkdtemp under $TMPDIR), removed with everything in it.
class Scratch_directory {
 public:
  Scratch_directory() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/fair-curves-serve-XXXXXX";
    if (!::mkdtemp(&pattern[0])) throw std::runtime_error(std::string("cannot make a scratch directory: ") + std::strerror(errno));
    path_ = pattern;
  }
  ~Scratch_directory() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  Scratch_directory(const Scratch_directory&) = delete;
  Scratch_directory& operator=(const Scratch_directory&) = delete;
  const std::string& path() const { return path_; }

  /// Writes a new file `name` (a name the server chose) with `text`.
  void write(const std::string& name, const std::string& text) const {
    const std::string file = path_ + "/" + name;
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    bool ok = fd >= 0;
    std::size_t done = 0;
    while (ok && done < text.size()) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n <= 0) ok = false;
      else done += static_cast<std::size_t>(n);
    }
    if (fd >= 0) ::close(fd);
    if (!ok) throw std::runtime_error("cannot write the scratch file " + name);
  }

  enum Read_result { missing, read_ok, too_big };

  /// The contents of the regular file `name`, at most `cap` bytes (review finding 5: the files
  /// the child writes count against the output cap as its pipes do).
  Read_result read(const std::string& name, std::string& text, std::size_t cap) const {
    const std::string file = path_ + "/" + name;
    const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return missing;
    struct stat st;
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
      ::close(fd);
      return missing;
    }
    if (static_cast<unsigned long long>(st.st_size) > cap) {
      ::close(fd);
      return too_big;
    }
    text.clear();
    text.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[65536];
    ssize_t n;
    while ((n = ::read(fd, buffer, sizeof buffer)) > 0) {
      text.append(buffer, static_cast<std::size_t>(n));
      if (text.size() > cap) break;
    }
    ::close(fd);
    if (text.size() > cap) return too_big;
    return n == 0 ? read_ok : missing;
  }

 private:
  std::string path_;
};

/// The rows of the metrics command's --profile CSV as the JSON array of /api/metrics.
std::string profile_json(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header: piece,t,arc_length,x,y,curvature
  static const char* names[] = {"piece", "t", "arc_length", "x", "y", "curvature"};
  std::string out = "[";
  bool first = true;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string f;
    while (std::getline(ss, f, ',')) fields.push_back(f);
    if (fields.size() != 6) continue;
    out += first ? "\n    {" : ",\n    {";
    first = false;
    for (int k = 0; k < 6; ++k) {
      char* end = nullptr;
      const double v = std::strtod(fields[std::size_t(k)].c_str(), &end);
      char buffer[40];
      if (k == 0) std::snprintf(buffer, sizeof buffer, "%lld", std::strtoll(fields[0].c_str(), nullptr, 10));
      else if (std::isfinite(v)) std::snprintf(buffer, sizeof buffer, "%.17g", v);
      else std::snprintf(buffer, sizeof buffer, "null");
      out += std::string(k ? ", " : "") + "\"" + names[k] + "\": " + buffer;
    }
    out += "}";
  }
  return out + (first ? "]" : "\n  ]");
}

class Server {
 public:
  Server(const Serve_options& options, std::vector<Method_info> table)
      : options_(options), table_(std::move(table)), methods_text_(methods_json(table_).dump(2) + "\n"),
        slots_(solve_slot_count()) {
    limits_.wall_seconds = options.solve_timeout;
  }

  /// Serves until SIGINT or SIGTERM; false when a connection's thread was still running after
  /// the grace period (the caller then ends the process without destroying the server).
  bool run() {
    net::io_context ioc;
    beast::error_code ec;
    const net::ip::address address = net::ip::make_address(options_.bind, ec);
    if (ec) throw CLI::ValidationError("--bind", "not an IP address: '" + options_.bind + "'");
    tcp::acceptor acceptor(ioc);
    const tcp::endpoint endpoint(address, static_cast<unsigned short>(options_.port));
    acceptor.open(endpoint.protocol(), ec);
    if (!ec) acceptor.set_option(net::socket_base::reuse_address(true), ec);
    if (!ec) acceptor.bind(endpoint, ec);
    if (!ec) acceptor.listen(net::socket_base::max_listen_connections, ec);
    if (ec) throw std::runtime_error("cannot listen on " + options_.bind + ":" + std::to_string(options_.port) + ": " + ec.message());
    ::fcntl(acceptor.native_handle(), F_SETFD, FD_CLOEXEC);
    const tcp::endpoint bound = acceptor.local_endpoint();
    const std::string host = bound.address().is_v6() ? "[" + bound.address().to_string() + "]" : bound.address().to_string();
    const std::string url = "http://" + host + ":" + std::to_string(bound.port()) + "/";
    if (bound.address().is_loopback()) {
      const std::string port = ":" + std::to_string(bound.port());
      for (const std::string& h : {std::string("localhost"), std::string("127.0.0.1"), std::string("[::1]"), host})
        allowed_hosts_.insert(h + port);
    }
    std::cout << "fair-curves serve: listening on " << url << std::endl;
    if (options_.open) open_browser(url);

    net::signal_set signals(ioc, SIGINT, SIGTERM);
    signals.async_wait([&](const beast::error_code&, int) {
      beast::error_code ignored;
      acceptor.close(ignored);
    });
    std::function<void()> accept = [&]() {
      acceptor.async_accept([&](const beast::error_code& e, tcp::socket socket) {
        if (!e) dispatch(std::move(socket));
        // e.g. out of descriptors: a pause instead of a busy loop of failing accepts
        else if (e != net::error::operation_aborted) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        if (acceptor.is_open()) accept();
        else signals.cancel();
      });
    };
    accept();
    ioc.run();

    // Stopping: no new connections; the children killed, the open connections shut down, and
    // their threads given a few seconds to end.
    std::cout << "fair-curves serve: stopped" << std::endl;
    std::unique_lock<std::mutex> lock(mutex_);
    stopping_ = true;
    slots_.stop();
    Child_registry::instance().kill_all();
    for (const int fd : open_fds_) ::shutdown(fd, SHUT_RDWR);
    return done_.wait_for(lock, std::chrono::seconds(5), [&] { return active_ == 0; });
  }

 private:
  /// A new connection: its own thread, or 503 when max_connections are served already.
  void dispatch(tcp::socket socket) {
    beast::error_code ec;
    ::fcntl(socket.native_handle(), F_SETFD, FD_CLOEXEC);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (active_ < max_connections && !stopping_) {
        ++active_;
        const int fd = socket.release(ec);
        if (ec) {
          --active_;
          return;
        }
        open_fds_.insert(fd);
        try {
          std::thread([this, fd] { connection(fd); }).detach();
          return;
        } catch (const std::system_error&) {  // no thread to be had: answer busy below
          --active_;
          open_fds_.erase(fd);
          socket.assign(tcp::v4(), fd, ec);
          if (ec) {
            ::close(fd);
            return;
          }
        }
      }
    }
    // Busy: a short answer written without blocking, then closed.
    http::response<http::string_body> res{http::status::service_unavailable, 11};
    res.set(http::field::content_type, "application/json");
    res.set(http::field::connection, "close");
    res.body() = error_json("server busy: " + std::to_string(max_connections) + " connections are served at once");
    res.prepare_payload();
    std::ostringstream text;
    text << res;
    socket.non_blocking(true, ec);
    net::write(socket, net::buffer(text.str()), ec);
    socket.shutdown(tcp::socket::shutdown_both, ec);
    socket.close(ec);
  }

  /// Runs one asynchronous operation of a connection to its end on the connection's io_context.
  template <class Start>
  static beast::error_code await(net::io_context& ioc, Start start) {
    beast::error_code result;
    bool done = false;
    start([&](const beast::error_code& ec, auto&&...) {
      result = ec;
      done = true;
    });
    // Until this operation's handler ran: a WebSocket keeps its idle timer waiting between
    // operations, so the context never runs out of work while the socket is open.
    ioc.restart();
    while (!done && ioc.run_one()) {
    }
    return result;
  }

  void connection(int fd) {
    {
      net::io_context ioc;
      beast::tcp_stream stream(ioc);
      beast::error_code ec;
      sockaddr_storage addr;
      socklen_t len = sizeof addr;
      const bool v6 = ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) == 0 && addr.ss_family == AF_INET6;
      stream.socket().assign(v6 ? tcp::v6() : tcp::v4(), fd, ec);
      if (!ec) serve_requests(ioc, stream);
      {
        std::lock_guard<std::mutex> lock(mutex_);
        open_fds_.erase(fd);  // before the close: the number may be reused at once
      }
      stream.socket().shutdown(tcp::socket::shutdown_both, ec);
      stream.socket().close(ec);
      if (ec) ::close(fd);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    --active_;
    done_.notify_all();
  }

  void serve_requests(net::io_context& ioc, beast::tcp_stream& stream) {
    beast::flat_buffer buffer;
    for (;;) {
      http::request_parser<http::string_body> parser;
      parser.header_limit(max_head);
      parser.body_limit(max_body);
      stream.expires_after(idle_timeout);
      beast::error_code ec = await(ioc, [&](auto handler) { http::async_read_header(stream, buffer, parser, handler); });
      Answer a;
      bool read_all = false;
      if (ec == http::error::header_limit) {
        a = error_answer(http::status::request_header_fields_too_large,
                         "the request head is over the cap of " + std::to_string(max_head) + " bytes");
      } else if (ec == http::error::body_limit) {
        a = error_answer(http::status::payload_too_large, "the request body is over the cap of 4 MiB");
      } else if (ec) {
        if (ec == beast::error::timeout || ec == http::error::end_of_stream || ec == net::error::eof ||
            ec == net::error::connection_reset || ec == net::error::operation_aborted || ec == net::error::broken_pipe)
          return;  // closed or idle: nothing to answer
        a = error_answer(http::status::bad_request, "malformed HTTP request: " + ec.message());
      } else {
        const bool post = parser.get().method() == http::verb::post;
        if (post && (parser.chunked() || !parser.content_length())) {
          a = error_answer(http::status::length_required, "a POST needs a Content-Length (and no chunked body)");
        } else if (parser.content_length() && *parser.content_length() > max_body) {
          a = error_answer(http::status::payload_too_large,
                           "the request body of " + std::to_string(*parser.content_length()) +
                               " bytes is over the cap of " + std::to_string(max_body) + " bytes (4 MiB)");
        } else {
          read_all = true;
          stream.expires_after(idle_timeout);
          // A client that waits for "100 Continue" before sending its body (curl does for large
          // bodies) gets it now that the head is accepted.
          const auto expect = parser.get().find(http::field::expect);
          if (expect != parser.get().end() && beast::iequals(expect->value(), "100-continue") && !parser.is_done()) {
            static const char continue_line[] = "HTTP/1.1 100 Continue\r\n\r\n";
            ec = await(ioc, [&](auto handler) {
              net::async_write(stream, net::buffer(continue_line, sizeof continue_line - 1), handler);
            });
            if (ec) return;
          }
          ec = await(ioc, [&](auto handler) { http::async_read(stream, buffer, parser, handler); });
          if (ec == http::error::body_limit) {
            a = error_answer(http::status::payload_too_large, "the request body is over the cap of 4 MiB");
            read_all = false;
          } else if (ec) {
            return;  // a half body, then the client went away or idled: nothing to answer
          } else if (websocket::is_upgrade(parser.get()) && target_path(parser.get()) == "/api/ws") {
            // The WebSocket of the drag steps: the same Host and Origin checks as every request.
            std::optional<Answer> refused = foreign(parser.get());
            if (!refused) {
              serve_websocket(ioc, stream, parser.release());
              return;
            }
            a = std::move(*refused);
          } else a = handle(parser.get(), stream.socket().native_handle());
        }
      }
      const bool keep_alive = read_all && !a.close && parser.is_done() && parser.get().keep_alive();
      http::response<http::string_body> res{a.status, 11};
      res.set(http::field::server, "fair-curves");
      res.set(http::field::content_type, a.content_type);
      res.set(http::field::cache_control, "no-store");
      res.set("X-Content-Type-Options", "nosniff");
      // The page works offline: it may load nothing from another origin.
      // No inline script (the page has none): script-src falls back to 'self'; inline styles stay.
      res.set("Content-Security-Policy", "default-src 'self' data: blob:; style-src 'self' 'unsafe-inline'");
      for (const auto& h : a.headers) res.set(h.first, h.second);
      res.keep_alive(keep_alive);
      // HEAD: the head of the GET answer, its Content-Length, and no body (review finding 10:
      // a body after a HEAD answer desynchronised a kept-alive connection).
      const bool head = read_all && parser.get().method() == http::verb::head;
      const std::size_t length = a.body.size();
      if (!head) res.body() = std::move(a.body);
      res.prepare_payload();
      if (head) res.content_length(length);
      stream.expires_after(write_timeout);
      ec = await(ioc, [&](auto handler) { http::async_write(stream, res, handler); });
      if (ec || !keep_alive) return;
    }
  }

  static std::string lower(beast::string_view v) {
    std::string h(v);
    for (char& c : h) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return h;
  }

  static std::string target_path(const http::request<http::string_body>& req) {
    std::string path(req.target());
    const std::size_t query = path.find('?');
    if (query != std::string::npos) path.resize(query);
    return path;
  }

  /// GET /api/ws upgraded (doc/editor_api.md, "WebSocket"): each text message is the body of a
  /// POST /api/solve and gets one text message back, the bytes /api/solve would answer, or on an
  /// error {"error", "status"[, "id"]}. The connection stays counted against max_connections.
  void serve_websocket(net::io_context& ioc, beast::tcp_stream& stream, http::request<http::string_body> req) {
    stream.expires_never();  // the websocket's own timers from here on
    websocket::stream<beast::tcp_stream&> ws(stream);
    websocket::stream_base::timeout timeouts;
    timeouts.handshake_timeout = write_timeout;
    timeouts.idle_timeout = ws_idle_timeout;
    timeouts.keep_alive_pings = false;
    ws.set_option(timeouts);
    ws.read_message_max(max_body);  // over it: closed with 1009 (message too big)
    // One frame a message, and no Nagle: a message written in pieces waited for the client's
    // delayed ACK (a 47 ms median drag round trip in the browser test before, measured).
    ws.auto_fragment(false);
    beast::error_code nodelay_ec;
    stream.socket().set_option(tcp::no_delay(true), nodelay_ec);
    ws.set_option(websocket::stream_base::decorator([](websocket::response_type& res) { res.set(http::field::server, "fair-curves"); }));
    beast::error_code ec = await(ioc, [&](auto handler) { ws.async_accept(req, handler); });
    if (ec) return;
    const int client_fd = stream.socket().native_handle();
    beast::flat_buffer buffer;
    for (;;) {
      buffer.clear();
      ec = await(ioc, [&](auto handler) { ws.async_read(buffer, handler); });
      if (ec) return;  // closed, idle, too big (Beast sent the close frame), or the server stops
      if (!ws.got_text()) {
        await(ioc, [&](auto handler) {
          ws.async_close(websocket::close_reason(websocket::close_code::unknown_data,
                                                 "binary messages are not accepted: send the JSON of a solve as text"),
                         handler);
        });
        return;
      }
      const std::string text = beast::buffers_to_string(buffer.data());
      nlohmann::json id;
      Answer a = api_request("/api/solve", [&] {
        nlohmann::json j = parse_body(text);
        // "id" (WebSocket only): echoed in an error answer; answers come in the order of the requests.
        if (j.is_object() && j.contains("id")) {
          if (!j["id"].is_number()) throw Request_error("id: expected a number, got " + type_name(j["id"]));
          id = j["id"];
          j.erase("id");
        }
        return j;
      }, client_fd);
      if (a.close) return;  // the client went away during a child's solve
      std::string out;
      if (a.status == http::status::ok) out = std::move(a.body);
      else {
        nlohmann::json e = nlohmann::json::parse(a.body, nullptr, false);
        if (!e.is_object()) e = nlohmann::json{{"error", a.body}};
        e["status"] = static_cast<int>(a.status);
        if (!id.is_null()) e["id"] = id;
        out = e.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
      }
      ws.text(true);
      ec = await(ioc, [&](auto handler) { ws.async_write(net::buffer(out), handler); });
      if (ec) return;
    }
  }

  /// Not this server's page: the Host is not one the server answers, or the Origin is foreign
  /// (the 403 answer); nullopt otherwise.
  std::optional<Answer> foreign(const http::request<http::string_body>& req) const {
    // Bound to loopback, the server answers only requests addressed to loopback: a web page
    // that rebinds its own host name to 127.0.0.1 (DNS rebinding) cannot use the API.
    const auto host = req.find(http::field::host);
    if (!allowed_hosts_.empty() && host != req.end()) {
      std::string h(host->value());
      for (char& c : h) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (!allowed_hosts_.count(h))
        return error_answer(http::status::forbidden, "Host '" + std::string(host->value()) +
                                                         "' is not this server (it answers localhost only)");
    }
    // Cross-site requests (review finding 2): a browser names the page's origin; only the
    // server's own page may use it. Bound to loopback, the origin must be http:// and an accepted
    // Host; otherwise it must be http:// and the request's own Host.
    const auto origin = req.find(http::field::origin);
    if (origin != req.end()) {
      const std::string o = lower(origin->value());
      const bool own = o.rfind("http://", 0) == 0 &&
                       (allowed_hosts_.empty() ? host != req.end() && o.substr(7) == lower(host->value())
                                               : allowed_hosts_.count(o.substr(7)) > 0);
      if (!own)
        return error_answer(http::status::forbidden, "Origin '" + std::string(origin->value()) +
                                                         "' is not this server's page (cross-site requests are refused)");
    }
    return std::nullopt;
  }

  /// `client_fd`: the request's connection, watched while a child solves (client gone: killed).
  Answer handle(const http::request<http::string_body>& req, int client_fd) {
    if (std::optional<Answer> refused = foreign(req)) return std::move(*refused);
    // Every POST must say Content-Type: application/json: a cross-site page can send that only
    // after a CORS preflight (OPTIONS), which the server refuses, so its POST never comes.
    if (req.method() == http::verb::post) {
      const auto type = req.find(http::field::content_type);
      std::string t = type == req.end() ? std::string() : lower(type->value());
      const std::size_t semicolon = t.find(';');
      if (semicolon != std::string::npos) t.resize(semicolon);
      while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.pop_back();
      while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.erase(0, 1);
      if (t != "application/json") {
        Answer a = error_answer(http::status::unsupported_media_type,
                                "Content-Type must be application/json (got " +
                                    (type == req.end() ? std::string("none") : "'" + std::string(type->value()) + "'") + ")");
        a.headers.emplace_back("Accept", "application/json");
        return a;
      }
    }
    std::string path(req.target());
    const std::size_t query = path.find('?');
    if (query != std::string::npos) path.resize(query);
    const bool get = req.method() == http::verb::get || req.method() == http::verb::head,
               post = req.method() == http::verb::post;
    auto wrong_method = [&](const char* allow) {
      Answer a = error_answer(http::status::method_not_allowed,
                              std::string(req.method_string()) + " " + path + ": method not allowed (use " + allow + ")");
      a.headers.emplace_back("Allow", allow);
      return a;
    };
    return answered([&]() -> Answer {
      if (path == "/api/methods") {
        if (!get) return wrong_method("GET, HEAD");
        Answer a;
        a.body = methods_text_;
        return a;
      }
      if (path == "/api/solve" || path == "/api/export" || path == "/api/metrics") {
        if (!post) return wrong_method("POST");
        // Server-Timing: the time the server spent on the request, so that a client can tell
        // it from the network's and the page's (the browser test's drag round trip).
        return api_request(path, [&] { return parse_body(req.body()); }, client_fd);
      }
      if (path == "/api/ws")
        return error_answer(http::status::upgrade_required, "GET /api/ws: a WebSocket upgrade is required");
      if (path.rfind("/api/", 0) == 0 || path == "/api") return error_answer(http::status::not_found, "no such API endpoint: " + path);
      if (!get) return wrong_method("GET, HEAD");
      const std::string name = path == "/" ? "index.html" : path.substr(1);
      Answer a;
      if (!find_asset(options_.editor_dir, name, a.body))
        return error_answer(http::status::not_found, "no such file of the editor: " + path);
      a.content_type = content_type(name);
      return a;
    });
  }

  /// What `f` answers, or the error answer of what it throws: a Request_error with its status, 503
  /// when memory ran out, 500 for anything else (a bug of the server, named).
  template <class F>
  Answer answered(F f) {
    try {
      return f();
    } catch (const Request_error& e) {
      return error_answer(static_cast<http::status>(e.status), e.what());
    } catch (const std::bad_alloc&) {
      return error_answer(http::status::service_unavailable, "server busy: out of memory");
    } catch (const std::exception& e) {
      return error_answer(http::status::internal_server_error, std::string("internal error: ") + e.what());
    }
  }

  /// One API request (`path` one of /api/solve, /api/export, /api/metrics) of the body `parse`
  /// returns: the POSTs' and the WebSocket's common path, its errors as answers.
  template <class Parse>
  Answer api_request(const std::string& path, Parse parse, int client_fd) {
    return answered([&]() -> Answer {
      const auto start = std::chrono::steady_clock::now();
      const nlohmann::json body = parse();
      Answer a = path == "/api/metrics" ? metrics(body, client_fd) : solve(body, path == "/api/export", client_fd);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      char timing[64];
      std::snprintf(timing, sizeof timing, "app;dur=%.3f", ms);
      a.headers.emplace_back("Server-Timing", timing);
      return a;
    });
  }

  Answer solve(const nlohmann::json& body, bool export_request, int client_fd) {
    const Solve_request r = parse_solve_request(body, table_, export_request);
    if (!export_request && Kappa_sessions::handles(r)) {
      Kappa_session_answer s = sessions_.solve(r, slots_, deadline_from_now());
      if (s.busy) return busy_answer();
      if (s.answered) {
        Answer a;
        a.body = std::move(s.json);
        return a;
      }
    }
    const Child_job job = solve_job(r);
    Answer a = run_job(job, client_fd);
    if (a.status == http::status::ok && export_request) {
      const std::string ext = r.format == "svg-path" ? "txt" : r.format;
      a.content_type = r.format == "dxf" ? "application/dxf" : r.format == "svg" ? "image/svg+xml"
                       : r.format == "svg-path" ? "text/plain; charset=utf-8" : "application/json";
      a.headers.emplace_back("Content-Disposition", "attachment; filename=\"curve." + ext + "\"");
    }
    return a;
  }

  Answer metrics(const nlohmann::json& body, int client_fd) {
    const Child_job job = metrics_job(body);
    return run_job(job, client_fd, "profile.csv");
  }

  /// Solves at once: one per core (at least 1; 2 when the number is unknown).
  static int solve_slot_count() {
    const unsigned n = std::thread::hardware_concurrency();
    return n ? static_cast<int>(n) : 2;
  }

  std::chrono::steady_clock::time_point deadline_from_now() const {
    return std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                  std::chrono::duration<double>(limits_.wall_seconds));
  }

  Answer busy_answer() const {
    return error_answer(http::status::service_unavailable,
                        "server busy: " + std::to_string(slots_.count()) +
                            " solves run at once (one per core) and none ended within the solve cap of " +
                            seconds_text(limits_.wall_seconds) + " s");
  }

  Answer output_cap_answer() const {
    return error_answer(http::status::service_unavailable,
                        "the solve wrote more than the cap of " + std::to_string(limits_.max_output >> 20) + " MiB");
  }

  /// Runs a job in a child in its own scratch directory; `profile`: the metrics' profile file,
  /// added to the JSON as "profile".
  Answer run_job(const Child_job& job, int client_fd, const std::string& profile = "") {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopping_) return error_answer(http::status::service_unavailable, "server busy: the server is stopping");
    }
    // A solve slot first; the wait counts against the solve's wall-clock cap.
    const auto deadline = deadline_from_now();
    const Solve_slot slot(slots_, deadline);
    if (!slot) return busy_answer();
    Child_limits limits = limits_;
    limits.wall_seconds = std::max(0.01, std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count());
    const Scratch_directory scratch;
    for (const auto& f : job.files) scratch.write(f.first, f.second);
    const Child_result c = run_child("/proc/self/exe", job.args, scratch.path(), limits, client_fd);
    if (c.client_gone) {  // nobody to answer: the connection is closed after this
      Answer gone = error_answer(http::status::service_unavailable, "the client closed the connection");
      gone.close = true;
      return gone;
    }
    if (!c.started) return error_answer(http::status::service_unavailable, "server busy: " + c.error);
    if (c.timed_out)
      return error_answer(http::status::service_unavailable,
                          "the solve did not finish within the cap of " + seconds_text(limits_.wall_seconds) + " s");
    if (c.output_overflow || c.signal == SIGXFSZ) return output_cap_answer();
    if (c.signal == SIGXCPU)
      return error_answer(http::status::service_unavailable, "the solve exceeded the CPU time cap of " +
                                                                 seconds_text(limits_.wall_seconds) + " s");
    // A SIGKILL the server did not send (the OOM killer, an operator): said as it is (finding 8).
    if (c.signal == SIGKILL)
      return error_answer(http::status::internal_server_error, "the solver process was killed (SIGKILL)");
    if (c.signal)
      return error_answer(http::status::internal_server_error,
                          "the solver process crashed (" + signal_name(c.signal) + ")");
    if (c.exit_code == 1 || c.exit_code == 2) {
      // Exactly what main.cpp writes for std::bad_alloc (a substring could be the user's text).
      if (c.err == "fair-curves: error: std::bad_alloc\n")
        return error_answer(http::status::service_unavailable, "the solve exceeded the memory cap of " +
                                                                   std::to_string(limits_.address_space >> 30) + " GiB");
      return error_answer(http::status::unprocessable_entity, program_message(c.err));
    }
    if (c.exit_code != 0 && c.exit_code != 3)
      return error_answer(http::status::internal_server_error,
                          "the solver process failed (exit code " + std::to_string(c.exit_code) + "): " + program_message(c.err));
    Answer a;
    if (job.answer_file.empty()) a.body = c.out;
    else {
      const auto got = scratch.read(job.answer_file, a.body, limits_.max_output);
      if (got == Scratch_directory::too_big) return output_cap_answer();
      if (got != Scratch_directory::read_ok)
        return error_answer(http::status::internal_server_error, "the program wrote no " + job.answer_file);
    }
    if (!profile.empty()) {
      std::string csv;
      const std::size_t end = a.body.rfind('}');
      const auto got = scratch.read(profile, csv, limits_.max_output - std::min(limits_.max_output, a.body.size()));
      if (got == Scratch_directory::too_big) return output_cap_answer();
      if (got != Scratch_directory::read_ok || end == std::string::npos)
        return error_answer(http::status::internal_server_error, "the metrics command wrote no profile");
      a.body.insert(end, ",\n  \"profile\": " + profile_json(csv) + "\n");
      // keep the closing brace on its own line as the program writes it
      const std::size_t brace = a.body.rfind('}');
      if (brace > 0 && a.body[brace - 1] == '\n' && brace > 1 && a.body[brace - 2] == '\n') a.body.erase(brace - 1, 1);
      if (a.body.size() > limits_.max_output) return output_cap_answer();
    }
    return a;
  }

  /// --open: xdg-open URL when it exists (reaped by a detached thread).
  static void open_browser(const std::string& url) {
    std::string found;
    if (const char* path = std::getenv("PATH")) {
      std::stringstream dirs(path);
      std::string dir;
      while (found.empty() && std::getline(dirs, dir, ':'))
        if (!dir.empty() && ::access((dir + "/xdg-open").c_str(), X_OK) == 0) found = dir + "/xdg-open";
    }
    if (found.empty()) {
      std::cout << "fair-curves serve: could not open a browser (no xdg-open): open " << url << std::endl;
      return;
    }
    std::vector<std::string> args{"xdg-open", url};
    std::vector<char*> argv{&args[0][0], &args[1][0], nullptr};
    const pid_t pid = ::fork();
    if (pid == 0) {
      // The browser it starts must not hold the server's stdout (a harness waiting for its end
      // would hang) nor its session (review finding 14).
      const int null_fd = ::open("/dev/null", O_RDWR);
      if (null_fd >= 0) {
        ::dup2(null_fd, 0);
        ::dup2(null_fd, 1);
        ::dup2(null_fd, 2);
      }
      ::setsid();
      ::execv(found.c_str(), argv.data());
      ::_exit(127);
    }
    if (pid > 0) std::thread([pid] { int status; ::waitpid(pid, &status, 0); }).detach();
    else std::cout << "fair-curves serve: could not open a browser: open " << url << std::endl;
  }

  Serve_options options_;
  std::vector<Method_info> table_;
  std::string methods_text_;
  Child_limits limits_;
  Solve_slots slots_;
  Kappa_sessions sessions_;
  std::mutex mutex_;
  std::condition_variable done_;
  std::set<int> open_fds_;
  std::set<std::string> allowed_hosts_;  ///< Host values accepted (bound to loopback), lower case
  int active_ = 0;
  bool stopping_ = false;
};

void run_serve(const Serve_options& options) {
  // The methods and their options from the program's own subcommands, built as main.cpp builds
  // them (this app is never parsed).
  CLI::App app;
  for (const fair_curves::Command_entry& c : fair_curves::command_registry()) c.add(app);
  ::signal(SIGPIPE, SIG_IGN);
  Server server(options, method_table(app));
  if (!server.run()) {
    // A connection's thread still runs (a solve in process): end without destroying what it uses.
    std::cout.flush();
    std::_Exit(0);
  }
}

} // namespace

void register_serve_command(CLI::App& app) {
  auto options = std::make_shared<Serve_options>();
  CLI::App* sub = app.add_subcommand(
      "serve", "The curve editor: an HTTP server of the editor page and its JSON API (doc/editor_api.md); "
               "every solve is the program's own answer");
  sub->add_option("--port", options->port, "TCP port (default 8080; 0: a free port, printed on the first line)")
      ->check(CLI::Range(0, 65535));
  sub->add_option("--bind", options->bind, "address to listen on (default 127.0.0.1: this machine only)");
  sub->add_flag("--open", options->open, "open the page in a browser (xdg-open)");
  sub->add_option("--editor-dir", options->editor_dir,
                  "serve the page's files from this folder instead of the copy compiled in (page development)")
      ->check(CLI::ExistingDirectory);
  sub->add_option("--solve-timeout", options->solve_timeout, "wall-clock cap of one solve in seconds (default 20)")
      ->check(CLI::Range(0.1, 3600.0));
  sub->footer("Caps: request body 4 MiB, request head 8 KiB, 20000 points, solve time --solve-timeout (20 s), "
              "solver address space 4 GiB, child output and files 64 MiB, one solve per core at once (more wait within the solve time), 32 connections at once (more: 503), a connection idle for 10 s is "
              "closed (an open WebSocket /api/ws: after 300 s without a message; messages 4 MiB), 64 kappa sessions of at most 2000 points and max-iterations 200, JSON nested at most 64 levels. Bound to loopback, "
              "only requests for localhost and without a foreign Origin are answered; every POST needs Content-Type: application/json. The first line on stdout is "
              "\"fair-curves serve: listening on http://HOST:PORT/\". SIGINT or SIGTERM stop the server.\n");
  sub->callback([options] { run_serve(*options); });
}
FAIR_CURVES_COMMAND(register_serve_command)
