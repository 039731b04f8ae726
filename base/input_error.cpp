#include "base/input_error.h"

#include <cstdio>

namespace boxlod {

std::string input_message(const std::string& file, const std::string& place, const std::string& what) {
    std::string message = file;
    if (!place.empty()) message += ": " + place;
    message += ": " + what;
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    while (!message.empty() && message.back() == ' ') message.pop_back();
    return message;
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
