// The small amount of JSON and query parsing rvu's web display needs: flat objects out,
// generations and cursor positions in. No JSON library: nothing nested is ever read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rvu/session.h"

namespace rp::rvu {

// A flat JSON object built in order: {"a":1,"b":"x"}.
class JsonObject {
public:
    void add(const std::string& key, const std::string& value);
    void add(const std::string& key, const char* value) { add(key, std::string(value)); }
    void add(const std::string& key, double value);  // non-finite numbers become null
    void add(const std::string& key, bool value);
    std::string text() const { return "{" + body_ + "}"; }

private:
    void key(const std::string& k);
    std::string body_;
};

// A JSON string literal: quotes, backslashes and control characters escaped; bytes that
// are not valid UTF-8 become U+FFFD so that the page always gets valid JSON.
std::string jsonString(const std::string& s);

// The answer to POST /command.
std::string commandJson(const CommandResult& r);
std::string errorJson(const std::string& message);

// "since=" values: a decimal generation; anything else counts as 0 (answer at once).
uint64_t parseGeneration(const std::string& s);
// "cursor=x,y" or "x1,y1,x2,y2": integers; false (and nothing stored) otherwise.
bool parseCursor(const std::string& s, std::vector<Cursor>& out);

}  // namespace rp::rvu
