// One table per enum: each value with the name that the command line,
// parameter files, sweep configs, the viewer and help texts all use, and a
// line of help. A table is a constexpr array beside its enum; these read it.
#pragma once
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace boxlod {

template <typename Enum>
struct EnumEntry {
    Enum value;
    const char* name;
    const char* help;
};

template <typename Enum>
std::optional<Enum> enum_from_name(std::span<const EnumEntry<Enum>> table, std::string_view name) {
    for (const EnumEntry<Enum>& entry : table)
        if (name == entry.name) return entry.value;
    return std::nullopt;
}

// Sets `value` and returns true when `name` is in the table.
template <typename Enum>
bool parse_enum(std::span<const EnumEntry<Enum>> table, std::string_view name, Enum& value) {
    std::optional<Enum> found = enum_from_name(table, name);
    if (found) value = *found;
    return found.has_value();
}

template <typename Enum>
const char* enum_name(std::span<const EnumEntry<Enum>> table, Enum value) {
    for (const EnumEntry<Enum>& entry : table)
        if (entry.value == value) return entry.name;
    return "?";
}

// The names for help and messages: "a, b, c", "a,b,c" (separator ","), or
// "a, b or c" (last ", or ").
template <typename Enum>
std::string enum_names(std::span<const EnumEntry<Enum>> table, std::string_view separator = ", ",
                       std::string_view last = {}) {
    if (last.empty()) last = separator;
    std::string out;
    for (std::size_t i = 0; i < table.size(); ++i)
        out.append(i == 0 ? "" : i + 1 == table.size() ? last : separator).append(table[i].name);
    return out;
}

// The value after `value` in the table, the first after the last (the viewer's keys).
template <typename Enum>
Enum next_enum(std::span<const EnumEntry<Enum>> table, Enum value) {
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table[i].value == value) return table[(i + 1) % table.size()].value;
    return table[0].value;
}

}  // namespace boxlod
