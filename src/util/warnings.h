// Warnings for the user. Tools install a sink that prefixes the program name; warnings
// that can repeat many times (runaway photons, short lookups) go through WarningCounter
// so they are reported once, with a count, at the end.
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include "util/error.h"

namespace rp {

using WarningSink = std::function<void(const std::string&)>;

// Replaces the sink (default: "warning: <msg>" on stderr). Not thread-safe to call
// while other threads warn; tools set it once at start-up.
void setWarningSink(WarningSink sink);

// Silences warnings while it lives and then puts the sink it found back (getbbox -w
// inside another tool).
class QuietWarnings {
public:
    QuietWarnings();
    ~QuietWarnings();
    QuietWarnings(const QuietWarnings&) = delete;
    QuietWarnings& operator=(const QuietWarnings&) = delete;

private:
    WarningSink saved_;
};

void warn(const std::string& message);
void warn(const SourceLoc& loc, const std::string& message);

// Counts occurrences of one kind of warning across threads; report() emits one line.
class WarningCounter {
public:
    explicit WarningCounter(std::string what) : what_(std::move(what)) {}
    void add(long n = 1) { count_.fetch_add(n, std::memory_order_relaxed); }
    long count() const { return count_.load(std::memory_order_relaxed); }
    // Emits "<count> <what>" if count > 0.
    void report() const;

private:
    std::string what_;
    std::atomic<long> count_{0};
};

}  // namespace rp
