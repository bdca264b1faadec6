// rvu's web display over real HTTP on loopback: only requests with the token, this
// server's Host and (when given) its own Origin are served; commands run and report as
// JSON, malformed ones included; the picture comes as PNG; quit ends the server.
#include "rvu/web_display.h"

#include <gtest/gtest.h>
#include <httplib.h>

#include <future>
#include <thread>

#include "calc/search_path.h"
#include "scene/reader.h"
#include "util/paths.h"

namespace rp::rvu {
namespace {

const char* kScene = R"(
void light bright 0 0 3 10 10 10
void plastic white 0 0 5 .7 .7 .7 0 0
white polygon floor 0 0 12  -5 -5 0  5 -5 0  5 5 0  -5 5 0
bright sphere lamp 0 0 4  0 0 3  0.5
)";

class WebDisplayTest : public ::testing::Test {
protected:
    void SetUp() override {
        SessionSetup s;
        s.scene = &scene_;
        s.geometry = &geometry_;
        s.searchPath = calc::defaultSearchPath(projectLibDir());
        s.options = rvuDefaults();
        s.options.picture.view.point = {0, -4, 2};
        s.options.picture.view.direction = {0, 1, -0.3};
        s.options.picture.xres = s.options.picture.yres = 48;
        session_ = std::make_unique<Session>(s);
        std::promise<std::string> url;
        auto announced = url.get_future();
        WebDisplayOptions o;
        o.stop = &stop_;
        o.announce = [&url](const std::string& u) { url.set_value(u); };
        server_ = std::thread([this, o] { runWebDisplay(*session_, o); });
        ASSERT_EQ(announced.wait_for(std::chrono::seconds(20)), std::future_status::ready);
        const std::string u = announced.get();
        // http://127.0.0.1:PORT/?t=TOKEN
        const size_t colon = u.find(':', 7), slash = u.find('/', colon);
        port_ = std::stoi(u.substr(colon + 1, slash - colon - 1));
        token_ = u.substr(u.find("t=") + 2);
        EXPECT_EQ(u.rfind("http://127.0.0.1:", 0), 0u);
        EXPECT_EQ(token_.size(), 32u);
    }
    void TearDown() override {
        stop_ = true;
        if (server_.joinable()) server_.join();
    }
    httplib::Client client() { return httplib::Client("127.0.0.1", port_); }
    httplib::Headers withToken(httplib::Headers h = {}) {
        h.emplace("X-Rvu-Token", token_);
        return h;
    }
    int status(const httplib::Result& r) { return r ? r->status : -1; }

    Scene scene_ = parseScene(kScene, "t.rad");
    SceneGeometry geometry_{scene_};
    std::unique_ptr<Session> session_;
    std::atomic<bool> stop_{false};
    std::thread server_;
    int port_ = 0;
    std::string token_;
};

TEST_F(WebDisplayTest, OnlyTheTokenHolderIsServed) {
    auto c = client();
    EXPECT_EQ(status(c.Get("/")), 403);
    EXPECT_EQ(status(c.Get("/?t=" + token_)), 200);
    EXPECT_EQ(status(c.Get("/?t=" + token_.substr(1) + "0")), 403);
    EXPECT_EQ(status(c.Get("/state")), 403);
    EXPECT_EQ(status(c.Get("/picture.png")), 403);
    EXPECT_EQ(status(c.Post("/command", "quit", "text/plain")), 403);
    EXPECT_EQ(status(c.Get("/state", withToken())), 200);
    // Another site's page (DNS rebinding, or a cross-site request with a leaked token).
    EXPECT_EQ(
        status(c.Get("/state", withToken({{"Host", "evil.example:" + std::to_string(port_)}}))),
        403);
    EXPECT_EQ(status(c.Post("/command", withToken({{"Origin", "http://evil.example"}}), "quit",
                            "text/plain")),
              403);
    const std::string port = std::to_string(port_);
    EXPECT_EQ(status(c.Get("/state", withToken({{"Origin", "http://127.0.0.1:" + port}}))), 200);
    // Another page on this machine (other port) may not send commands, even with the token.
    EXPECT_EQ(status(c.Get("/state", withToken({{"Origin", "http://127.0.0.1:1"}}))), 403);
    EXPECT_EQ(status(c.Get("/state", withToken({{"Origin", "http://localhost:" + port}}))), 403);
    EXPECT_EQ(status(c.Get("/state", withToken({{"Host", "localhost:" + port},
                                                {"Origin", "http://localhost:" + port}}))),
              200);
    // Through a forwarded port (ssh -L 8080:127.0.0.1:PORT) the page names that port.
    EXPECT_EQ(status(c.Get("/state", withToken({{"Host", "127.0.0.1:8080"},
                                                {"Origin", "http://127.0.0.1:8080"}}))),
              200);
    EXPECT_EQ(status(c.Get("/state", withToken({{"Host", "127.0.0.1:8080x"}}))), 403);
    EXPECT_EQ(status(c.Get("/state", withToken({{"Host", "127.0.0.1:"}}))), 403);
    EXPECT_EQ(status(c.Get("/state", withToken({{"Host", "127.0.0.1"}}))), 200);  // port 80
    EXPECT_EQ(status(c.Get("/state", withToken({{"Host", "[::1]"}}))), 200);
    EXPECT_EQ(status(c.Get("/state", withToken({{"Host", "127.0.0.2:" + port}}))), 403);
    EXPECT_EQ(status(c.Get("/state", withToken({{"Host", "localhost.evil.example:" + port}}))),
              403);
    EXPECT_EQ(status(c.Get("/nothing", withToken())), 404);
}

TEST_F(WebDisplayTest, CommandsAnswerInJsonAndQuitEnds) {
    auto c = client();
    auto r = c.Post("/command", withToken(), "nosuch 1 2", "text/plain");
    ASSERT_EQ(status(r), 200);
    EXPECT_EQ(r->body, R"({"ok":false,"error":"nosuch: unknown command"})");
    r = c.Post("/command", withToken(), "aim", "text/plain");
    EXPECT_EQ(r->body, R"({"ok":false,"pick":"Pick view center","points":1})");
    r = c.Post("/command?cursor=1,2,x", withToken(), "aim", "text/plain");
    EXPECT_NE(r->body.find("bad cursor position"), std::string::npos);
    r = c.Post("/command?cursor=40,24", withToken(), "aim 1", "text/plain");
    EXPECT_EQ(r->body, R"({"ok":true,"output":""})");
    r = c.Post("/command", withToken(), "exposure =2", "text/plain");
    EXPECT_EQ(r->body, R"({"ok":true,"output":"exposure 2"})");
    r = c.Get("/state?since=0", withToken());
    ASSERT_EQ(status(r), 200);
    EXPECT_NE(r->body.find(R"("exposure":2)"), std::string::npos) << r->body;
    EXPECT_NE(r->body.find(R"("width":48)"), std::string::npos) << r->body;
    r = c.Get("/picture.png", withToken());
    ASSERT_EQ(status(r), 200);
    EXPECT_EQ(r->body.substr(1, 3), "PNG");
    EXPECT_FALSE(r->get_header_value("X-Rvu-Generation").empty());
    r = c.Post("/command", withToken(), "quit", "text/plain");
    EXPECT_EQ(r->body, R"({"ok":true,"output":"","quit":true})");
    server_.join();                                              // ends by itself
    EXPECT_EQ(status(client().Get("/state", withToken())), -1);  // nobody listens
}

}  // namespace
}  // namespace rp::rvu
