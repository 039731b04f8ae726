// Compact JSON text as nlohmann's dump() writes it (toolkit/formats/json_text.h).
#include "toolkit/formats/json_text.h"

#include "base/utf8.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace boxlod {

void JsonText::open(char bracket, bool object) {
    element();
    text += bracket;
    levels_.push_back({object, true, {}});
}

void JsonText::begin_object() { open('{', true); }
void JsonText::begin_array() { open('[', false); }

// Closes the innermost level, which must be of that kind.
void JsonText::close(bool object) {
    if (levels_.empty() || levels_.back().object != object)
        throw std::logic_error("JSON text: nothing of that kind to close");
    levels_.pop_back();
    text += object ? '}' : ']';
}

void JsonText::end_object() { close(true); }
void JsonText::end_array() { close(false); }

// Before a value: in an array, the comma before every element but the first
// (in an object its key wrote it).
void JsonText::element() {
    if (levels_.empty()) return;
    if (levels_.back().object) {  // after its key: the key wrote the comma
        if (text.empty() || text.back() != ':')
            throw std::logic_error("JSON text: a value without a key in an object");
        return;
    }
    if (!levels_.back().empty) text += ',';
    levels_.back().empty = false;
}

void JsonText::key(std::string_view name) {
    if (levels_.empty() || !levels_.back().object)
        throw std::logic_error("JSON text: a key outside an object");
    Level& level = levels_.back();
    if (!level.empty && name <= level.last_key)
        throw std::logic_error("JSON text: key '" + std::string(name) + "' out of order");
    if (!level.empty) text += ',';
    level.empty = false;
    level.last_key = name;
    quoted(name);
    text += ':';
}

void JsonText::string(std::string_view value) {
    element();
    quoted(value);
}

void JsonText::quoted(std::string_view value) {
    if (!is_utf8(value)) throw std::logic_error("JSON text: a string that is not UTF-8");
    text += '"';
    for (char c : value) {
        switch (c) {
        case '"': text += "\\\""; break;
        case '\\': text += "\\\\"; break;
        case '\b': text += "\\b"; break;
        case '\f': text += "\\f"; break;
        case '\n': text += "\\n"; break;
        case '\r': text += "\\r"; break;
        case '\t': text += "\\t"; break;
        default:
            if ((unsigned char)(c) < 0x20) {
                static const char hex[] = "0123456789abcdef";
                text += "\\u00";
                text += hex[(unsigned char)(c) >> 4];
                text += hex[c & 15];
            } else {
                text += c;
            }
        }
    }
    text += '"';
}

void JsonText::integer(std::int64_t value) {
    element();
    char buffer[24];
    text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

void JsonText::boolean(bool value) {
    element();
    text += value ? "true" : "false";
}

void JsonText::null() {
    element();
    text += "null";
}

void JsonText::raw(std::string_view json) {
    element();
    text += json;
}

// nlohmann's dtoa_impl::format_buffer laid over the shortest digits
// (std::to_chars): the point after n of the k digits.
void JsonText::number(double value) {
    element();
    if (!std::isfinite(value)) {
        text += "null";
        return;
    }
    if (value == 0) {
        text += std::signbit(value) ? "-0.0" : "0.0";
        return;
    }
    char scientific[32];
    const char* end =
        std::to_chars(scientific, scientific + sizeof scientific, value, std::chars_format::scientific).ptr;
    const char* e = static_cast<const char*>(std::memchr(scientific, 'e', std::size_t(end - scientific)));
    char digits[24];
    int k = 0;
    for (const char* p = scientific; p < e; ++p)
        if (*p >= '0' && *p <= '9') digits[k++] = *p;
    int exponent = 0;
    std::from_chars(e + (e[1] == '+' ? 2 : 1), end, exponent);
    const int n = exponent + 1;
    if (value < 0) text += '-';
    if (k <= n && n <= 15) {  // digits[000].0
        text.append(digits, std::size_t(k));
        text.append(std::size_t(n - k), '0');
        text += ".0";
    } else if (0 < n && n <= 15) {  // dig.its
        text.append(digits, std::size_t(n));
        text += '.';
        text.append(digits + n, std::size_t(k - n));
    } else if (-4 < n && n <= 0) {  // 0.[000]digits
        text += "0.";
        text.append(std::size_t(-n), '0');
        text.append(digits, std::size_t(k));
    } else {  // d.igitse+XX, at least two exponent digits
        text += digits[0];
        if (k > 1) {
            text += '.';
            text.append(digits + 1, std::size_t(k - 1));
        }
        text += n - 1 < 0 ? "e-" : "e+";
        const int shown = std::abs(n - 1);
        if (shown < 10) text += '0';
        text += std::to_string(shown);
    }
}

}  // namespace boxlod
