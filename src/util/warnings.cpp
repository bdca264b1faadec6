#include "util/warnings.h"

#include <cstdio>
#include <mutex>
#include <utility>

namespace rp {

namespace {
std::mutex sinkMutex;
void toStderr(const std::string& m) { std::fprintf(stderr, "warning: %s\n", m.c_str()); }
WarningSink& sink() {
    static WarningSink s = toStderr;
    return s;
}
}  // namespace

// An empty sink restores the default (tests reset theirs that way).
void setWarningSink(WarningSink s) { sink() = s ? std::move(s) : WarningSink(toStderr); }

QuietWarnings::QuietWarnings() {
    std::lock_guard<std::mutex> lock(sinkMutex);
    saved_ = std::exchange(sink(), [](const std::string&) {});
}

QuietWarnings::~QuietWarnings() {
    std::lock_guard<std::mutex> lock(sinkMutex);
    sink() = std::move(saved_);
}

void warn(const std::string& message) {
    std::lock_guard<std::mutex> lock(sinkMutex);
    sink()(message);
}

void warn(const SourceLoc& loc, const std::string& message) {
    std::string where = loc.str();
    warn(where.empty() ? message : where + ": " + message);
}

void WarningCounter::report() const {
    long n = count();
    if (n > 0) warn(std::to_string(n) + " " + what_);
}

}  // namespace rp
