#include "base/key_values.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace boxlod {

std::string format_number(double value) {
    if (value == 0) return "0";  // also turns -0 into 0
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string format_number(float value) {
    if (value == 0) return "0";
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

KeyValue float_entry(std::string key, float value) { return {std::move(key), format_number(value), true}; }
KeyValue number_entry(std::string key, double value) { return {std::move(key), format_number(value), true}; }
KeyValue text_entry(std::string key, std::string value) { return {std::move(key), std::move(value), false}; }

KeyValue numbers_entry(std::string key, const std::vector<double>& values) {
    std::string text;
    for (double value : values) {
        if (!text.empty()) text += ',';
        text += format_number(value);
    }
    return text_entry(std::move(key), std::move(text));
}

std::string value_of(const KeyValues& entries, const std::string& key) {
    for (const KeyValue& e : entries)
        if (e.key == key) return e.value;
    return "";
}

std::string format_key_values(const KeyValues& entries) {
    std::string out;
    for (const KeyValue& e : entries) out += e.key + " = " + e.value + "\n";
    return out;
}

namespace {
std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        } else
            out += char(c);
    }
    return out + "\"";
}
}  // namespace

std::string format_json(const KeyValues& entries) {
    std::string out = "{";
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const KeyValue& e = entries[i];
        out +=
            (i ? ",\n  " : "\n  ") + json_string(e.key) + ": " + (e.number ? e.value : json_string(e.value));
    }
    return out + "\n}\n";
}

std::vector<std::string> comma_list(std::string_view text) {
    std::vector<std::string> items;
    for (std::size_t begin = 0;;) {
        const std::size_t end = std::min(text.find(',', begin), text.size());
        std::string_view item = text.substr(begin, end - begin);
        const std::size_t first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
        items.emplace_back(first == std::string_view::npos ? std::string_view()
                                                           : item.substr(first, last - first + 1));
        if (end == text.size()) return items;
        begin = end + 1;
    }
}

}  // namespace boxlod
