#include "base/input_error.h"

#include <cstdio>

namespace boxlod {

namespace {

// Room for two paths of PATH_MAX and more; a message quoting a file's bytes (tinygltf quotes a bad
// data: URI whole) is cut there, at a character's first byte.
constexpr std::size_t longest_line = 10000;

std::string printable_line(const std::string& text) {
    std::string line;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (line.size() >= longest_line && (byte & 0xc0) != 0x80) {
            line += " ... (" + std::to_string(text.size()) + " bytes in all)";
            break;
        }
        if (c == '\n' || c == '\r') {
            line += ' ';
        } else if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
            line += escaped;
        } else {
            line += c;
        }
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    return line;
}

}  // namespace

InputError::InputError(const std::string& message) : std::runtime_error(printable_line(message)) {}

std::string input_message(const std::string& file, const std::string& place, const std::string& what) {
    std::string message = file;
    if (!place.empty()) message += ": " + place;
    return printable_line(message + ": " + what);
}

std::string range_text(const NumberRange& range) {
    auto number = [](double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.10g", v);
        return std::string(buffer);
    };
    std::string text = "[";  // appended, not "[" + ...: GCC 12's false -Wrestrict
    text += number(range.min);
    text += ", ";
    text += number(range.max);
    return text + "]";
}

std::string out_of_range_message(const NumberRange& range, const std::string& text) {
    return "expected a number in " + range_text(range) + ", got '" + text + "'";
}

std::string nesting_message() {
    return "nested more than " + std::to_string(max_nesting_depth) + " levels deep";
}

}  // namespace boxlod
