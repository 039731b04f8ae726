#include "toolkit/formats/json_input.h"

#include "base/input_error.h"
#include "base/memory_budget.h"

#include <cstdint>

namespace boxlod {
namespace {

// What one scan counts of a JSON text, outside strings but for their lengths.
struct JsonCounts {
    std::uint64_t containers = 0, separators = 0, members = 0, strings = 0, string_bytes = 0;
    std::size_t too_deep_at = std::string_view::npos;  // the byte of the first bracket past max_nesting_depth
};

JsonCounts count_json(std::string_view json) {
    JsonCounts counts;
    int depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (in_string) {
            ++counts.string_bytes;
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
            ++counts.strings;
        } else if (c == '[' || c == '{') {
            ++counts.containers;
            if (++depth > max_nesting_depth && counts.too_deep_at == std::string_view::npos)
                counts.too_deep_at = i;
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == ',') {
            ++counts.separators;
        } else if (c == ':') {
            ++counts.members;
        }
    }
    return counts;
}

// nlohmann::json on 64-bit libstdc++: a value is 16 bytes (48 as its array
// grows, old and new buffer held at once), an array or object 24-48 more on the heap, an object member a map
// node (32) with its key (32) and value, a string 32 on the heap and, past
// 15 bytes, its bytes in an allocation of their own; 16 bytes of malloc's
// per allocation, rounded up to 16.
double tree_bytes(const JsonCounts& n) {
    const double values = double(n.separators + n.containers + 1);
    return 48 * values + 64 * double(n.containers) + 96 * double(n.members) + 64 * double(n.strings) +
           double(n.string_bytes);
}

}  // namespace

double json_tree_bytes(std::string_view json) { return tree_bytes(count_json(json)); }

void check_json_input(std::string_view json, const std::string& file, double trees, const std::string& what) {
    const JsonCounts counts = count_json(json);
    if (counts.too_deep_at != std::string_view::npos)
        throw_input_error(file, "byte " + std::to_string(counts.too_deep_at), "JSON " + nesting_message());
    check_memory(file + ": " + what, trees * tree_bytes(counts));
}

}  // namespace boxlod
