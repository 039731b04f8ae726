#include "toolkit/key_value_lines.h"

#include "renderer/input_error.h"

#include <sstream>

namespace boxlod {
namespace {

std::string trim(const std::string& s) {
    std::size_t begin = s.find_first_not_of(" \t\r"), end = s.find_last_not_of(" \t\r");
    return begin == std::string::npos ? "" : s.substr(begin, end - begin + 1);
}

}  // namespace

std::vector<KeyValueLine> parse_key_value_lines(const std::string& text, const std::string& file) {
    std::vector<KeyValueLine> lines;
    std::istringstream in(text);
    std::string raw;
    for (int number = 1; std::getline(in, raw); ++number) {
        std::string content = trim(raw.substr(0, raw.find('#')));
        if (content.empty()) continue;
        std::size_t equals = content.find('=');
        if (equals == std::string::npos) throw_input_error(file, "line " + std::to_string(number), "expected 'key = value'");
        lines.push_back({number, trim(content.substr(0, equals)), trim(content.substr(equals + 1))});
    }
    return lines;
}

}  // namespace boxlod
