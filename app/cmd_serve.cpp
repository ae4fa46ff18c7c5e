// `brdfnav serve`: the navigation interface of the paper (sections 3.3 and 4) as a page in the
// browser, over the JSON API of serve_api.h (docs/SERVE.md). The page is embedded in the binary;
// nothing is fetched from anywhere else.
#include <brdfnav/serve/lightings.h>
#include <brdfnav/serve/serve_api.h>
#include <brdfnav/serve/serve_memory.h>
#include <brdfnav/serve/web_assets.h>
#include "commands.h"

#include <ImfThreading.h>
#include <OpenImageIO/imageio.h>
#include <httplib.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <thread>

namespace brdfnav::cli {

namespace {

// Pool threads answering connections: enough for a few browser tabs' keep-alive connections
// (6 each) and a burst of API requests beside them.
constexpr int kServeThreads = 64;

// How long nothing is asked before the server gives back what only queries in flight need
// (IdleRelease): longer than an artist's pause between two clicks, so that the next click
// rarely pays for reading pages back.
constexpr std::chrono::seconds kIdleRelease{10};

struct ServeOptions {
  std::vector<std::string> dbs;  // one per lighting, the first shown first
  std::string host = "127.0.0.1";
  int port = 8080;
  int resolution = 128;
};

// Every answer goes out through here; a failure is logged with its message as the API wrote it
// (httplib compresses the body after the handler for a client that accepts gzip or br, so the
// logger would see compressed bytes).
void reply(const httplib::Request& req, httplib::Response& res, const serve::ApiResponse& answer) {
  if (answer.status >= 400)
    std::fprintf(stderr, "brdfnav: serve: %s %s -> %d %s\n", req.method.c_str(), req.path.c_str(),
                 answer.status, answer.body.c_str());
  res.status = answer.status;
  res.set_content(answer.body, answer.content_type.c_str());
  for (const auto& [name, value] : answer.headers) res.set_header(name.c_str(), value);
}

const serve::WebAsset* find_asset(const std::string& path) {
  const std::string wanted = path == "/" ? "/index.html" : path;
  for (const serve::WebAsset& asset : serve::web_assets())
    if (asset.path == wanted) return &asset;
  return nullptr;
}

void add_routes(httplib::Server& server, const serve::LightingsApi& api, serve::IdleRelease& idle) {
  const auto handle = [&api, &idle](const httplib::Request& req, httplib::Response& res) {
    const serve::IdleRelease::Busy busy(idle);
    reply(req, res, api.handle({req.method, req.path, req.params, req.body}));
  };
  // Every POST and every request under /api/ is the API's (which refuses the methods a path
  // does not take with 405); other GETs are the page's files.
  server.Get("/api/.*", handle);
  server.Post(".*", handle);
  server.Put("/api/.*", handle).Patch("/api/.*", handle).Delete("/api/.*", handle);
  server.Options("/api/.*", handle);
  server.Get("/.*", [](const httplib::Request& req, httplib::Response& res) {
    if (const serve::WebAsset* asset = find_asset(req.path)) {
      res.set_content(std::string(asset->body), std::string(asset->content_type).c_str());
    } else {
      res.status = 404;
    }
  });
}

// What httplib refused before any handler ran. Debian's cpp-httplib 0.11 (a compiled library, so
// its macros cannot be changed here) refuses form-encoded bodies over 8192 bytes whatever the
// payload limit, and curl -d sends that type; a POST without Content-Length is its 400.
std::string refusal(const httplib::Request& req, int status) {
  const std::string request = req.method + " " + req.path;
  if (status == 404) return request + ": not found";
  if (status != 413)
    return request + ": malformed HTTP request (status " + std::to_string(status) + ")";
  if (req.get_header_value("Content-Type").rfind("application/x-www-form-urlencoded", 0) == 0)
    return "body: larger than 8192 bytes, httplib's limit for application/x-www-form-urlencoded "
           "(send the request as application/json)";
  return "body: larger than " + std::to_string(serve::kMaxBodyBytes) + " bytes";
}

// Every failure answers in the API's form: {"error": ...} with 400 for the client's mistakes.
void add_error_handling(httplib::Server& server) {
  server.set_payload_max_length(serve::kDrainedBodyBytes);
  using Handled = httplib::Server::HandlerResponse;
  server.set_error_handler(httplib::Server::HandlerWithResponse([](const httplib::Request& req,
                                                                   httplib::Response& res) {
    if (!res.body.empty()) return Handled::Unhandled;  // an API answer
    // httplib refuses a body over the limit with 413; the API reports every bad request as
    // 400 naming the field.
    reply(req, res,
          serve::error_response(res.status == 413 ? 400 : res.status, refusal(req, res.status)));
    return Handled::Handled;
  }));
  server.set_exception_handler(
      [](const httplib::Request& req, httplib::Response& res, std::exception_ptr error) {
        try {
          std::rethrow_exception(error);
        } catch (const std::exception& e) {
          reply(req, res, serve::error_response(500, e.what()));
        } catch (...) {
          reply(req, res, serve::error_response(500, "unknown error"));
        }
      });
  // The page loads nothing but its own files and the thumbnails it fetches.
  server.set_default_headers(
      {{"Content-Security-Policy", "default-src 'self'; img-src 'self' blob:; object-src 'none'"},
       {"X-Content-Type-Options", "nosniff"},
       {"Cache-Control", "no-store"}});
}

// httplib serves each connection on one pool thread, which then waits up to the keep-alive
// timeout for the connection's next request: with its default 8 threads, a browser's 6 idle
// connections and a burst of requests kept others waiting a whole timeout each (docs/SERVE.md,
// Memory). An idle thread costs next to nothing.
void size_for_bursts(httplib::Server& server) {
  server.new_task_queue = [] { return new httplib::ThreadPool(kServeThreads); };
}

int bind(httplib::Server& server, const ServeOptions& o) {
  // httplib's default adds SO_REUSEPORT, with which a second server shares the port silently
  // and gets half the requests; SO_REUSEADDR alone still allows a restart at once.
  socket_t listening = INVALID_SOCKET;  // the last socket tried is the one bound
  server.set_socket_options([&listening](socket_t sock) {
    const int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    listening = sock;
  });
  const int port = o.port == 0 ? server.bind_to_any_port(o.host)
                               : (server.bind_to_port(o.host, o.port) ? o.port : -1);
  if (port <= 0)
    throw Error(ErrorCode::io, "--port",
                "cannot listen on " + o.host + ":" + std::to_string(o.port) +
                    " (in use, or not an address of this machine)");
  // Debian's compiled httplib listens with a backlog of 5: a burst of connections beyond it
  // while the accepting thread is busy has its SYNs dropped, and a client gives up after its
  // connect timeout (undici's 10 s; seen under ASan on a loaded machine). Listening again on
  // the bound socket raises the backlog.
  if (::listen(listening, SOMAXCONN) != 0)
    throw Error(
        ErrorCode::io, "--port",
        "cannot listen on " + o.host + ":" + std::to_string(port) + ": " + std::strerror(errno));
  return port;
}

std::string url(const std::string& host, int port) {
  const bool ipv6 = host.find(':') != std::string::npos;
  return "http://" + (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port) + "/";
}

// Final images are blends only where the database's blend check vouches for them, at its own
// resolution: say when none can be, so that a slow page has its reason in the log.
void warn_of_rendered_finals(const Database& db, int resolution) {
  const Manifest& m = db.manifest();
  std::string missing;
  for (const ProfileGrid& g : m.grids)
    if (db.blend_checks(g.model).empty())
      missing += (missing.empty() ? "" : ", ") + std::string(model_info(g.model).name);
  const std::string why = !blend_checks_current(m)
                              ? "format version " + std::to_string(m.format_version) +
                                    ", checked with an earlier spline"
                              : "built before it";
  if (!missing.empty())
    std::fprintf(stderr,
                 "brdfnav: warning: %s: no blend check for %s (%s): every final image of these "
                 "models is rendered; rebuild the database for quicker rings\n",
                 db.dir().c_str(), missing.c_str(), why.c_str());
  else if (resolution != m.resolution)
    std::fprintf(stderr,
                 "brdfnav: warning: --resolution %d is not the database's %d: every final image "
                 "is rendered (blends are vouched for at the database's resolution only)\n",
                 resolution, m.resolution);
}

// The write end of the pipe that on_stop_signal() writes to, and the handler: write() is
// async-signal-safe.
int stop_pipe_write = -1;
extern "C" void on_stop_signal(int) {
  const char byte = 1;
  [[maybe_unused]] const ssize_t written = ::write(stop_pipe_write, &byte, 1);
}

void serve(const ServeOptions& o) {
  // SIGINT and SIGTERM stop the server cleanly whichever thread they reach: a handler, not a
  // signal mask, since libraries start threads of their own before main() (OpenBLAS's pthreads
  // build does), which no mask set here would cover. The handler writes to a pipe that the
  // waiter below reads.
  int stop_pipe[2];
  if (::pipe(stop_pipe) != 0)
    throw std::runtime_error(std::string("serve: pipe: ") + std::strerror(errno));
  stop_pipe_write = stop_pipe[1];
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  action.sa_flags = SA_RESTART;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);

  // OpenEXR on the calling threads: its pool (OpenImageIO sizes it to the machine when it opens
  // an EXR) handed each small database image's rows to other threads and back, which under 8
  // pages at once cost more in futex hand-offs than the reading itself; the pool threads here
  // are many already.
  OIIO::attribute("exr_threads", -1);
  Imf::setGlobalThreadCount(0);
  // One heap per core for the request threads, not glibc's eight: its slack would multiply
  // (docs/SERVE.md, Memory).
  serve::limit_heap_arenas(std::max(1, static_cast<int>(std::thread::hardware_concurrency())));

  // The port first: opening a database verifies every file's checksum (seconds for the default
  // one), and a port in use should not wait for that. Connections made meanwhile wait in the
  // listening socket's backlog until the routes are in place.
  httplib::Server server;
  add_error_handling(server);
  size_for_bursts(server);
  const int port = bind(server, o);
  std::vector<serve::ApiOptions> databases;
  for (const std::string& db : o.dbs) databases.push_back(serve::ApiOptions{db, o.resolution});
  std::unique_ptr<const serve::LightingsApi> api;
  with_context("--db", [&] { api = std::make_unique<const serve::LightingsApi>(databases); });
  serve::IdleRelease idle(kIdleRelease, [&api] { api->release_memory(); });
  add_routes(server, *api, idle);
  for (std::size_t i = 0; i < api->size(); ++i)
    warn_of_rendered_finals(api->api(i).navigator().database(), o.resolution);
  if (o.host != "127.0.0.1" && o.host != "localhost" && o.host != "::1")
    std::fprintf(stderr, "brdfnav: warning: --host %s: reachable from other machines\n",
                 o.host.c_str());
  for (std::size_t i = 0; i < api->size(); ++i)
    std::printf("brdfnav: lighting %s: %s\n", api->id(i).c_str(),
                api->api(i).navigator().database().dir().c_str());
  std::printf("brdfnav: navigator for %s at %s (Ctrl-C stops)\n", o.dbs.front().c_str(),
              url(o.host, port).c_str());
  std::fflush(stdout);

  std::thread waiter([&] {
    char byte = 0;
    while (::read(stop_pipe[0], &byte, 1) < 0 && errno == EINTR) {
    }
    server.stop();
  });
  const bool ok = server.listen_after_bind();
  const char wake = 0;  // the waiter, if no signal came
  [[maybe_unused]] const ssize_t written = ::write(stop_pipe[1], &wake, 1);
  waiter.join();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  ::close(stop_pipe[0]);
  ::close(stop_pipe[1]);
  if (!ok) throw std::runtime_error("serve: the server stopped on an error");
  std::puts("brdfnav: stopped");
}

}  // namespace

void add_serve_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "serve", "Serve the navigator in the browser: a material, its variations, one radius");
  auto o = std::make_shared<ServeOptions>();
  cmd->add_option("--db", o->dbs,
                  "Database directory (brdfnav precompute); several, one per lighting, to switch "
                  "between them on the page (the first is shown first)")
      ->required();
  cmd->add_option("--port", o->port, "TCP port (0: any free port)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  cmd->add_option("--host", o->host, "Address to listen on")->capture_default_str();
  cmd->add_option("--resolution", o->resolution, "Thumbnail width and height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(8, 1024));
  cmd->callback([o] { serve(*o); });
}

}  // namespace brdfnav::cli
