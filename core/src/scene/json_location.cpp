// Finds the JSON path of a syntax error by parsing with a SAX handler that tracks the path.
#include "scene/json_location.hpp"
#include <nlohmann/json.hpp>
#include <vector>

namespace spt::detail {
namespace {

using json = nlohmann::json;

// Keeps the path of the value being read: one frame per open object or array.
class PathTracker : public nlohmann::json_sax<json> {
public:
    std::string path() const {
        std::string p;
        for (const Frame& f : stack_) p += f.array ? "/" + std::to_string(f.index) : (f.key.empty() ? "" : "/" + f.key);
        return p.empty() ? "/" : p;
    }
    std::string reason;
    size_t position = 0;

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool key(string_t& k) override {
        stack_.back().key = k;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t pos, const std::string&, const nlohmann::detail::exception& ex) override {
        position = pos;
        reason = ex.what();
        return false;
    }

private:
    struct Frame {
        bool array = false;
        size_t index = 0;
        std::string key;
    };
    bool value() {
        if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
        return true;
    }
    bool open(bool array) {
        stack_.push_back({array, 0, {}});
        return true;
    }
    bool close() {
        stack_.pop_back();
        return value();
    }
    std::vector<Frame> stack_;
};

} // namespace

std::string json_syntax_problem(const std::string& text) {
    PathTracker t;
    if (json::sax_parse(text, &t)) return {};
    size_t line = 1, col = 1;
    for (size_t i = 0; i + 1 < t.position && i < text.size(); ++i) {
        if (text[i] == '\n') ++line, col = 1;
        else ++col;
    }
    std::string reason = t.reason;
    const size_t colon = reason.rfind(": ");
    if (colon != std::string::npos) reason = reason.substr(colon + 2); // drop nlohmann's own prefix
    return "line " + std::to_string(line) + ", column " + std::to_string(col) + ", at " + t.path() +
           ": invalid JSON: " + reason;
}

} // namespace spt::detail
