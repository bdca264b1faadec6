// rvu's display: a web page served by rvu itself (cpp-httplib) on 127.0.0.1 only. The
// page shows the picture as it refines and takes rvu's commands; the rendering and the
// commands run on the calling thread, the HTTP requests on the server's threads.
//
// Who may talk to it: every request must carry the random token printed in the address
// (query t= or header X-Rvu-Token), name a loopback host in its Host header (no DNS
// rebinding; any port, for forwarded ports) and, when it has an Origin, come from the
// page of that same address. Anything
// else is refused with 403, so that another page in the user's browser can neither read
// the picture nor send `write` or `quit`.
//
// The page's API: GET / (the page), GET /state?since=G (JSON, waits up to 10 s for a
// generation after G), GET /picture.png (the display as PNG), POST /command (a command
// line as the body, optional cursor=x,y[,x2,y2] in picture pixels from the bottom
// left; JSON with ok/output/error/pick/points/quit). src/rvu/page.cpp is the page.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>

#include "rvu/session.h"

namespace rp::rvu {

struct WebDisplayOptions {
    int port = 0;                 // 0: a free port
    std::optional<double> gamma;  // display gamma (RADIANCE's DISPLAY_GAMMA); sRGB if unset
    // Told the page's address (with its token) once the server listens.
    std::function<void(const std::string& url)> announce;
    // Set (e.g. by a signal handler) to end the run as quit does.
    const std::atomic<bool>* stop = nullptr;
};

// Serves `session` until the quit command or *stop. Throws InputError when the port
// cannot be bound.
void runWebDisplay(Session& session, const WebDisplayOptions& options);

}  // namespace rp::rvu
