// rvu's web display (see web_display.h). cpp-httplib from Debian serves the page; we
// only route, check who is asking, and hand commands to the rendering thread.
#include "rvu/web_display.h"

#include <fmt/format.h>
#include <httplib.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <future>
#include <mutex>
#include <random>
#include <thread>

#include "image/png.h"
#include "image/tonemap.h"
#include "rvu/page.h"
#include "rvu/web_json.h"
#include "util/error.h"

namespace rp::rvu {

namespace {

using Clock = std::chrono::steady_clock;

std::string randomToken() {
    std::random_device device;  // getrandom(2) on Linux
    std::string t;
    for (int i = 0; i < 4; ++i) t += fmt::format("{:08x}", uint32_t(device()));
    return t;
}

// What the page sees: the display as the last publish left it.
struct Snapshot {
    uint64_t generation = 0;
    Picture picture;  // display values before exposure
    double exposure = 1;
    bool greyscale = false;
    std::string status, view;
    bool done = false, quit = false;
};

struct PendingCommand {
    std::string line;
    std::vector<Cursor> cursor;
    std::promise<CommandResult> result;
};

class WebDisplay {
public:
    WebDisplay(Session& session, const WebDisplayOptions& options)
        : session_(session), options_(options), token_(randomToken()) {}

    void run();

private:
    // The rendering thread's loop: commands first, refinement while there are none.
    void serve();
    bool allowed(const httplib::Request& req) const;
    void routes();
    void publish(bool quit = false);
    // Runs the queued commands; returns whether one was quit.
    bool runCommands();
    std::string stateJson(uint64_t since);
    std::string picturePng(uint64_t& generation);
    CommandResult submit(std::string line, std::vector<Cursor> cursor);

    Session& session_;
    const WebDisplayOptions& options_;
    const std::string token_;
    int port_ = 0;
    httplib::Server server_;

    std::mutex queueMutex_;
    std::condition_variable queueChanged_;
    std::deque<std::shared_ptr<PendingCommand>> queue_;
    std::atomic<bool> pending_{false};
    bool closed_ = false;  // under queueMutex_: no more commands are taken

    std::mutex snapshotMutex_;
    std::condition_variable published_;
    Snapshot snapshot_;
    Clock::time_point lastPublish_;

    std::mutex pngMutex_;
    uint64_t pngGeneration_ = 0;
    std::string png_;
};

// A loopback name, with any port: a page reached through a forwarded port (ssh -L
// 8080:127.0.0.1:PORT) names the forwarded one. Another site's name (DNS rebinding) is
// refused.
bool loopbackHost(const std::string& host) {
    std::string name = host;
    const size_t colon = host.rfind(':');
    if (colon != std::string::npos && host.back() != ']') {  // a port (none: port 80)
        if (colon + 1 == host.size() ||
            host.find_first_not_of("0123456789", colon + 1) != std::string::npos)
            return false;
        name = host.substr(0, colon);
    }
    return name == "127.0.0.1" || name == "localhost" || name == "[::1]";
}

bool WebDisplay::allowed(const httplib::Request& req) const {
    const std::string host = req.get_header_value("Host");
    if (!loopbackHost(host)) return false;
    // Only this page's own requests: same origin as the address it was loaded from.
    if (req.has_header("Origin") && req.get_header_value("Origin") != "http://" + host)
        return false;
    const std::string token = req.has_header("X-Rvu-Token") ? req.get_header_value("X-Rvu-Token")
                                                            : req.get_param_value("t");
    // Compared in full whatever the first difference, so timing tells nothing.
    if (token.size() != token_.size()) return false;
    unsigned diff = 0;
    for (size_t i = 0; i < token.size(); ++i) diff |= unsigned(token[i] ^ token_[i]);
    return diff == 0;
}

std::string WebDisplay::stateJson(uint64_t since) {
    std::unique_lock<std::mutex> lock(snapshotMutex_);
    published_.wait_for(lock, std::chrono::seconds(10),
                        [&] { return snapshot_.generation > since || snapshot_.quit; });
    const Snapshot& s = snapshot_;
    JsonObject j;
    j.add("generation", double(s.generation));
    j.add("width", double(s.picture.width));
    j.add("height", double(s.picture.height));
    j.add("status", s.status);
    j.add("done", s.done);
    j.add("exposure", s.exposure);
    j.add("view", s.view);
    j.add("quit", s.quit);
    return j.text();
}

std::string WebDisplay::picturePng(uint64_t& generation) {
    std::lock_guard<std::mutex> pngLock(pngMutex_);
    Snapshot s;
    {
        std::lock_guard<std::mutex> lock(snapshotMutex_);
        if (snapshot_.generation == pngGeneration_ && !png_.empty()) {
            generation = pngGeneration_;
            return png_;
        }
        s = snapshot_;
    }
    if (s.greyscale)
        for (Pixel& p : s.picture.pixels) p.fill(float(pixelBrightness(p)));
    png_ = encodePng(s.picture.width, s.picture.height,
                     toDisplayRgb8(s.picture, s.exposure, options_.gamma), options_.gamma);
    pngGeneration_ = generation = s.generation;
    return png_;
}

CommandResult WebDisplay::submit(std::string line, std::vector<Cursor> cursor) {
    auto command = std::make_shared<PendingCommand>();
    command->line = std::move(line);
    command->cursor = std::move(cursor);
    std::future<CommandResult> result = command->result.get_future();
    {
        std::lock_guard<std::mutex> lock(queueMutex_);
        if (closed_) {
            CommandResult r;
            r.ok = false;
            r.error = "rvu has ended";
            return r;
        }
        queue_.push_back(command);
        pending_ = true;
    }
    queueChanged_.notify_all();
    return result.get();
}

void WebDisplay::routes() {
    server_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
        if (allowed(req)) return httplib::Server::HandlerResponse::Unhandled;
        res.status = 403;
        res.set_content("rvu: forbidden (open the address rvu printed)\n", "text/plain");
        return httplib::Server::HandlerResponse::Handled;
    });
    server_.Get("/", [](const httplib::Request&, httplib::Response& res) {
        // The token is in this page's address: keep it out of Referer headers, frames
        // and caches.
        res.set_header("Referrer-Policy", "no-referrer");
        res.set_header("X-Frame-Options", "DENY");
        res.set_header("Cache-Control", "no-store");
        res.set_header("Content-Security-Policy",
                       "default-src 'none'; img-src 'self' blob: data:; style-src 'unsafe-inline'; "
                       "script-src 'unsafe-inline'; connect-src 'self'; frame-ancestors 'none'");
        res.set_content(std::string(pageHtml()), "text/html; charset=utf-8");
    });
    server_.Get("/state", [this](const httplib::Request& req, httplib::Response& res) {
        uint64_t since = 0;
        if (req.has_param("since")) since = parseGeneration(req.get_param_value("since"));
        res.set_header("Cache-Control", "no-store");
        res.set_content(stateJson(since), "application/json");
    });
    server_.Get("/picture.png", [this](const httplib::Request&, httplib::Response& res) {
        uint64_t generation = 0;
        std::string png = picturePng(generation);
        res.set_header("X-Rvu-Generation", std::to_string(generation));
        res.set_header("Cache-Control", "no-store");
        res.set_content(std::move(png), "image/png");
    });
    server_.Post("/command", [this](const httplib::Request& req, httplib::Response& res) {
        std::vector<Cursor> cursor;
        std::string error;
        if (req.has_param("cursor") && !parseCursor(req.get_param_value("cursor"), cursor))
            error = "bad cursor position \"" + req.get_param_value("cursor") + "\"";
        const CommandResult r = error.empty() ? submit(req.body, cursor) : CommandResult{};
        res.set_header("Cache-Control", "no-store");
        res.set_content(error.empty() ? commandJson(r) : errorJson(error), "application/json");
    });
    server_.set_exception_handler(
        [](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
            std::string what = "internal error";
            try {
                std::rethrow_exception(ep);
            } catch (const std::exception& e) {
                what = e.what();
            } catch (...) {
            }
            res.status = 500;
            res.set_content(errorJson(what), "application/json");
        });
    // Long polls hold a thread each; a few pages at once must not starve the commands.
    server_.new_task_queue = [] { return new httplib::ThreadPool(16); };
    server_.set_payload_max_length(64 * 1024);
    // An idle keep-alive connection holds up stop() for this long (cpp-httplib 0.11).
    server_.set_keep_alive_timeout(1);
    // cpp-httplib's default also sets SO_REUSEPORT, which would let a second rvu bind
    // the same -o web:PORT and receive half of the first one's requests.
    server_.set_socket_options([](socket_t sock) {
        int yes = 1;
        setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
    });
}

void WebDisplay::publish(bool quit) {
    {
        std::lock_guard<std::mutex> lock(snapshotMutex_);
        Snapshot& s = snapshot_;
        const ProgressiveImage& image = session_.image();
        s.picture.width = image.width();
        s.picture.height = image.height();
        s.picture.pixels = image.pixels();
        s.exposure = session_.exposure();
        s.greyscale = session_.greyscale();
        s.status = quit ? "quit" : session_.status();
        s.view = formatView(session_.view()).substr(1);
        s.done = session_.done();
        s.quit = quit;
        ++s.generation;
    }
    lastPublish_ = Clock::now();
    published_.notify_all();
}

bool WebDisplay::runCommands() {
    for (;;) {
        std::shared_ptr<PendingCommand> command;
        {
            std::lock_guard<std::mutex> lock(queueMutex_);
            if (queue_.empty()) {
                pending_ = false;
                return false;
            }
            command = queue_.front();
            queue_.pop_front();
        }
        const CommandResult r = session_.execute(command->line, command->cursor);
        if (r.quit) {
            std::lock_guard<std::mutex> lock(queueMutex_);
            closed_ = true;
        } else {
            publish();  // before the answer: the page's next /state shows the change
        }
        command->result.set_value(r);
        if (r.quit) return true;
    }
}

void WebDisplay::run() {
    routes();
    if (options_.port > 0)
        port_ = server_.bind_to_port("127.0.0.1", options_.port) ? options_.port : -1;
    else
        port_ = server_.bind_to_any_port("127.0.0.1");
    if (port_ <= 0) throw InputError(fmt::format("cannot listen on 127.0.0.1:{}", options_.port));
    std::thread listener([this] { server_.listen_after_bind(); });
    try {
        serve();
    } catch (...) {
        server_.stop();
        listener.join();
        throw;
    }
    server_.stop();
    listener.join();
}

void WebDisplay::serve() {
    const std::string url = fmt::format("http://127.0.0.1:{}/?t={}", port_, token_);
    auto stopping = [this] { return options_.stop && options_.stop->load(); };
    bool announced = false;
    for (;;) {
        if (stopping() || runCommands()) break;
        if (!session_.done()) {
            session_.refine([&] { return pending_.load() || stopping(); },
                            [&] {
                                // Mid-level pictures, a few per second.
                                if (Clock::now() - lastPublish_ > std::chrono::milliseconds(200))
                                    publish();
                            });
            publish();
        } else {
            std::unique_lock<std::mutex> lock(queueMutex_);
            queueChanged_.wait_for(lock, std::chrono::milliseconds(250),
                                   [&] { return !queue_.empty(); });
        }
        // The address is given once the first picture is there to show.
        if (!announced && options_.announce) options_.announce(url);
        announced = true;
    }
    {
        std::lock_guard<std::mutex> lock(queueMutex_);
        closed_ = true;
        CommandResult ended;
        ended.ok = false;
        ended.error = "rvu has ended";
        for (auto& c : queue_) c->result.set_value(ended);
        queue_.clear();
    }
    publish(true);
    // Let the quit answer and the last state reach the page before the server closes.
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
}

}  // namespace

void runWebDisplay(Session& session, const WebDisplayOptions& options) {
    WebDisplay display(session, options);
    display.run();
}

}  // namespace rp::rvu
