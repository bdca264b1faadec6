// Test-only: collects the warnings given while it lives (util/warnings.h), then puts the
// default sink back. Included by *_test.cpp files only.
#pragma once

#include <string>
#include <vector>

#include "util/warnings.h"

namespace rp {

class WarningCapture {
public:
    WarningCapture() {
        setWarningSink([this](const std::string& m) { lines.push_back(m); });
    }
    ~WarningCapture() { setWarningSink(nullptr); }
    WarningCapture(const WarningCapture&) = delete;
    WarningCapture& operator=(const WarningCapture&) = delete;

    // Whether some warning contains `part`.
    bool any(const std::string& part) const {
        for (const auto& m : lines)
            if (m.find(part) != std::string::npos) return true;
        return false;
    }
    std::vector<std::string> lines;
};

}  // namespace rp
