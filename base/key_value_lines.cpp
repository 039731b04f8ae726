#include "base/key_value_lines.h"

#include "base/input_error.h"

#include <cstdio>
#include <map>
#include <sstream>

namespace boxlod {

namespace {

// A comment starts at a '#' that begins the line or follows a blank, so that
// a value may hold one (a city file's object: district.city.json#house_3).
std::size_t comment_start(const std::string& line) {
    for (std::size_t at = line.find('#'); at != std::string::npos; at = line.find('#', at + 1))
        if (at == 0 || line[at - 1] == ' ' || line[at - 1] == '\t') return at;
    return std::string::npos;
}

std::string trim(const std::string& s) {
    std::size_t begin = s.find_first_not_of(" \t\r"), end = s.find_last_not_of(" \t\r");
    return begin == std::string::npos ? "" : s.substr(begin, end - begin + 1);
}

}  // namespace

std::vector<KeyValueLine> parse_key_value_lines(const std::string& text, const std::string& file) {
    std::vector<KeyValueLine> lines;
    std::map<std::string, int> first_line;
    // A UTF-8 byte-order mark, as some editors write, is no part of the first key.
    std::istringstream in(text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text);
    std::string raw;
    for (int number = 1; std::getline(in, raw); ++number) {
        for (unsigned char c : raw)
            if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
                char byte[8];
                std::snprintf(byte, sizeof byte, "0x%02x", unsigned(c));
                throw_input_error(file, "line " + std::to_string(number),
                                  std::string("not text (byte ") + byte + ")");
            }
        std::string content = trim(raw.substr(0, comment_start(raw)));
        if (content.empty()) continue;
        std::size_t equals = content.find('=');
        if (equals == std::string::npos)
            throw_input_error(file, "line " + std::to_string(number), "expected 'key = value'");
        std::string key = trim(content.substr(0, equals));
        if (auto [first, added] = first_line.emplace(key, number); !added)
            throw_input_error(file, "line " + std::to_string(number) + ": " + key,
                              "given twice (first on line " + std::to_string(first->second) + ")");
        lines.push_back({number, key, trim(content.substr(equals + 1))});
    }
    return lines;
}

}  // namespace boxlod
