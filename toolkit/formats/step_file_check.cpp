#include "toolkit/formats/step_file_check.h"

#include "base/graph_check.h"
#include "base/input_error.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace boxlod {
namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
    while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
    return text;
}

// Where the STEP string opening at text[i] ends: its closing quote ('' is a
// quote inside it), or text.size() if none.
std::size_t step_string_end(std::string_view text, std::size_t i) {
    for (++i; i < text.size() && !(text[i] == '\'' && (i + 1 >= text.size() || text[i + 1] != '\'')); ++i)
        if (text[i] == '\'') ++i;
    return i;
}

// The file with its comments (/* ... */ outside strings) made spaces, so that a '#' in one names nothing.
std::string blank_comments(std::string_view bytes) {
    std::string text(bytes);
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\'') {  // a string; '' is a quote inside it
            i = step_string_end(text, i);
        } else if (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            const std::size_t end = std::min(text.find("*/", i + 2), text.size() - 2) + 2;
            std::fill(text.begin() + std::ptrdiff_t(i), text.begin() + std::ptrdiff_t(end), ' ');
            i = end - 1;
        }
    }
    return text;
}

// "#N" (not "#" + ...: GCC 12's false -Wrestrict).
std::string instance_place(std::uint64_t id) { return std::to_string(id).insert(0, 1, '#'); }

// web-ifc keeps 32 bits of an entity number: a larger one would stand for another entity.
constexpr std::uint64_t max_entity_number = 4294967295;  // 2^32 - 1

// The entity number after the '#' at text[at - 1], within [1, max_entity_number]; `at` moves past it.
// `place` names the instance it is in.
std::uint64_t entity_number(std::string_view text, std::size_t& at, const std::string& file,
                            const std::string& place) {
    const std::size_t first = at;
    while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) ++at;
    if (at == first) throw_input_error(file, place, "'#' without an entity number");
    std::uint64_t id = 0;
    if (std::from_chars(text.data() + first, text.data() + at, id).ec != std::errc() || id == 0 ||
        id > max_entity_number)
        throw_input_error(
            file, std::string(text.substr(first, std::min<std::size_t>(at - first, 24))).insert(0, 1, '#'),
            "entity number outside [1, " + std::to_string(max_entity_number) + "]");
    return id;
}

// ISO 10303-21 instances as a graph: each instance's references, and for the
// IFC relationships assimp walks as a tree, the relating object's children;
// whether the file defines it, and the first instance that names it.
struct StepGraph {
    std::vector<std::uint64_t> ids, first_user;
    std::vector<std::vector<std::uint32_t>> references, children;
    std::vector<bool> defined;
    std::unordered_map<std::uint64_t, std::uint32_t> index;

    std::uint32_t node(std::uint64_t id, std::uint64_t user) {
        auto [it, added] = index.emplace(id, std::uint32_t(ids.size()));
        if (added) {
            ids.push_back(id);
            first_user.push_back(user);
            references.emplace_back();
            children.emplace_back();
            defined.push_back(false);
        }
        return it->second;
    }
};

// IFC's relationships that make the spatial tree: the relating and related attributes' positions (IFC2x3
// and IFC4).
struct Relationship {
    const char* type;
    int relating, related;
};
constexpr Relationship relationships[] = {{"IFCRELAGGREGATES", 4, 5},
                                          {"IFCRELNESTS", 4, 5},
                                          {"IFCRELCONTAINEDINSPATIALSTRUCTURE", 5, 4},
                                          {"IFCRELVOIDSELEMENT", 4, 5},
                                          {"IFCRELFILLSELEMENT", 4, 5}};

// A type's name in either case, as ISO 10303-21 allows.
const Relationship* relationship_of(std::string_view type) {
    for (const Relationship& r : relationships)
        if (std::equal(type.begin(), type.end(), r.type, r.type + std::char_traits<char>::length(r.type),
                       [](char a, char b) { return std::toupper(static_cast<unsigned char>(a)) == b; }))
            return &r;
    return nullptr;
}

// One instance, `#N = TYPE(attributes)` (or a complex one, `#N = (A(...) B(...))`), the text of its
// statement before the ';': its references and relationships into `graph`.
void read_instance(std::string_view text, const std::string& file, StepGraph& graph) {
    std::size_t i = 1;
    const std::uint64_t id = entity_number(text, i, file, std::string(text.substr(0, 24)));
    const std::string place = instance_place(id);
    while (i < text.size() && is_space(text[i])) ++i;
    if (i >= text.size() || text[i] != '=')
        throw_input_error(file, place, "expected '#N = TYPE(...);' (ISO 10303-21 section 11)");
    ++i;
    while (i < text.size() && is_space(text[i])) ++i;
    std::size_t type_end = i;
    while (type_end < text.size() && (std::isalnum(static_cast<unsigned char>(text[type_end])) ||
                                      text[type_end] == '_' || text[type_end] == '!'))
        ++type_end;
    const std::string_view type = text.substr(i, type_end - i);
    i = type_end;
    while (i < text.size() && is_space(text[i])) ++i;
    if (i >= text.size() || text[i] != '(')
        throw_input_error(file, place,
                          "its type '" + std::string(type.substr(0, 40)) + "' is not followed by '('");
    const std::uint32_t instance = graph.node(id, id);
    if (graph.defined[instance]) throw_input_error(file, place, "defined twice");
    graph.defined[instance] = true;
    const Relationship* relationship = relationship_of(type);
    std::vector<std::uint32_t> relating, related;
    int depth = 0, attribute = 0;
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\'') {
            i = step_string_end(text, i);
        } else if (c == '(') {
            ++depth;
        } else if (c == ')') {
            if (--depth == 0) break;
        } else if (c == ',' && depth == 1) {
            ++attribute;
        } else if (c == '#') {
            std::size_t at = i + 1;
            const std::uint32_t target = graph.node(entity_number(text, at, file, place), id);
            graph.references[instance].push_back(target);
            if (relationship && attribute == relationship->relating) relating.push_back(target);
            if (relationship && attribute == relationship->related) related.push_back(target);
            i = at - 1;
        }
    }
    if (depth != 0) throw_input_error(file, place, "its parentheses do not close before its ';'");
    if (!trimmed(text.substr(i + 1)).empty())
        throw_input_error(file, place, "text after its attributes before its ';' (a ';' missing?)");
    for (std::uint32_t parent : relating)
        graph.children[parent].insert(graph.children[parent].end(), related.begin(), related.end());
}

// A statement's first word, to name it.
std::string leading(std::string_view statement) {
    return std::string(statement.substr(0, std::min<std::size_t>(statement.find_first_of("=( \t\r\n"), 24)));
}

// Whether a statement is `keyword` or starts with it and '(' or a space, in either case (web-ifc reads
// "data;" too).
bool is_keyword(std::string_view statement, std::string_view keyword) {
    return statement.size() >= keyword.size() &&
           std::equal(keyword.begin(), keyword.end(), statement.begin(),
                      [](char a, char b) { return a == std::toupper(static_cast<unsigned char>(b)); }) &&
           (statement.size() == keyword.size() || statement[keyword.size()] == '(' ||
            is_space(statement[keyword.size()]));
}

// The statements of the file, each up to its ';' (strings skipped): instances are read in a DATA section
// and refused outside one (web-ifc reads them anywhere; ISO 10303-21 sections 8 and 9).
StepGraph read_step_graph(std::string_view bytes, const std::string& file) {
    StepGraph graph;
    bool in_data = false, any_data = false;
    for (std::size_t start = 0, i = 0; i < bytes.size(); ++i) {
        if (bytes[i] == '\'') i = step_string_end(bytes, i);
        if (i >= bytes.size() || bytes[i] != ';') continue;
        const std::string_view statement = trimmed(bytes.substr(start, i - start));
        start = i + 1;
        if (!statement.empty() && statement[0] == '#') {
            if (!in_data)
                throw_input_error(file, leading(statement),
                                  "an instance outside a DATA section (ISO 10303-21 section 9)");
            read_instance(statement, file, graph);
        } else if (is_keyword(statement, "DATA")) {
            in_data = any_data = true;
        } else if (is_keyword(statement, "ENDSEC")) {
            in_data = false;
        } else if (in_data && !statement.empty()) {
            throw_input_error(file, leading(statement),
                              "a statement in a DATA section that is no instance '#N = TYPE(...)' (ISO "
                              "10303-21 section 11)");
        }
    }
    if (!any_data) throw_input_error(file, "", "has no DATA section ('DATA;', ISO 10303-21 section 9)");
    // web-ifc leaves out what a dangling reference leads to without a word: the first one in the file.
    for (std::size_t n = 0; n < graph.ids.size(); ++n)
        if (!graph.defined[n])
            throw_input_error(file, instance_place(graph.first_user[n]),
                              "names " + instance_place(graph.ids[n]) + ", which the file does not define");
    return graph;
}

}  // namespace

void check_step_file(std::string_view bytes, const std::string& file, int max_depth) {
    std::size_t end = bytes.find_last_not_of(" \t\r\n");
    constexpr std::string_view trailer = "END-ISO-10303-21;";
    if (end == std::string_view::npos || end + 1 < trailer.size() ||
        bytes.substr(end + 1 - trailer.size(), trailer.size()) != trailer)
        throw_input_error(file, "", "does not end with 'END-ISO-10303-21;' (truncated file?)");
    StepGraph graph = read_step_graph(blank_comments(bytes), file);
    const auto place_of = [&](std::uint32_t node) { return instance_place(graph.ids[node]); };
    check_acyclic_and_shallow(graph.references, place_of, "references", file, max_depth);
    check_acyclic_and_shallow(graph.children, place_of, "spatial relationships", file, max_depth);
}

}  // namespace boxlod
