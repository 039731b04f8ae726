#include "toolkit/formats/xml_file_check.h"

#include "base/graph_check.h"
#include "base/input_error.h"
#include "base/number_text.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace boxlod {
namespace {

// Calls visit(at, tag) for each tag of an XML file (`tag` its text from '<' to '>', quoted attribute values
// held whole), skipping comments, CDATA sections, processing instructions and declarations; the text
// between tags is left to the visitor.
template <typename Visit>
void for_each_xml_tag(std::string_view bytes, Visit&& visit) {
    static constexpr std::pair<std::string_view, std::string_view> skipped[] = {
        {"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}};
    for (std::size_t i = bytes.find('<'); i != std::string_view::npos; i = bytes.find('<', i + 1)) {
        const auto skip = std::find_if(std::begin(skipped), std::end(skipped), [&](const auto& pair) {
            return bytes.substr(i, pair.first.size()) == pair.first;
        });
        if (skip != std::end(skipped)) {
            i = bytes.find(skip->second, i);
            if (i == std::string_view::npos) return;
            continue;
        }
        std::size_t end = i + 1;
        for (char quote = 0; end < bytes.size() && (quote || bytes[end] != '>'); ++end)
            if (bytes[end] == '"' || bytes[end] == '\'')
                quote = quote == bytes[end] ? 0 : quote ? quote : bytes[end];
        if (end >= bytes.size()) return;
        visit(i, bytes.substr(i, end + 1 - i));
        i = end;
    }
}

// The value of attribute `name` in an XML tag (its text from '<' to '>'), if the tag has it.
std::optional<std::string_view> xml_attribute(std::string_view tag, std::string_view name) {
    const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
        std::size_t i = at + name.size();
        while (i < tag.size() && space(tag[i])) ++i;
        if (at == 0 || !space(tag[at - 1]) || i >= tag.size() || tag[i] != '=') continue;
        for (++i; i < tag.size() && space(tag[i]);) ++i;
        if (i >= tag.size() || (tag[i] != '"' && tag[i] != '\'')) continue;
        const std::size_t end = tag.find(tag[i], i + 1);
        if (end == std::string_view::npos) return std::nullopt;
        return tag.substr(i + 1, end - i - 1);
    }
    return std::nullopt;
}

// A COLLADA tag's element name without a namespace prefix ("float_array" of <c:float_array ...>).
std::string_view collada_element(std::string_view tag) {
    std::string_view name = tag.substr(1, tag.find_first_of(" \t\r\n/>", 1) - 1);
    return name.substr(name.find(':') == std::string_view::npos ? 0 : name.find(':') + 1);
}

struct ColladaAccessor {
    std::size_t at;  // its byte in the file
    std::string source;
    std::size_t offset, count, stride, params;
};

// Each accessor reads within its array: offset + (count - 1) x stride + its params values, without overflow.
void check_collada_accessors(const std::vector<ColladaAccessor>& accessors,
                             const std::unordered_map<std::string, std::size_t>& array_values,
                             const std::string& file) {
    for (const ColladaAccessor& accessor : accessors) {
        const auto array = array_values.find(accessor.source);
        std::size_t reach = 0;  // offset + (count - 1) x stride + params, without overflow
        if (array == array_values.end() || accessor.count == 0) continue;
        if (!checked_multiply(accessor.count - 1, accessor.stride, reach) ||
            !range_fits(accessor.offset, reach, array->second) ||
            !range_fits(accessor.offset + reach, accessor.params, array->second))
            throw_input_error(file, "byte " + std::to_string(accessor.at) + " <accessor>",
                              "reads past its array " + accessor.source + " of " +
                                  std::to_string(array->second) +
                                  " values (offset + (count - 1) x stride + its params)");
    }
}

// COLLADA's arrays and accessors (COLLADA 1.4.1 specification, chapter 5: float_array, accessor): an array
// holds at least the values its count says, and an accessor reads within its array: offset + (count - 1) x
// stride + its params values at most (interleaved accessors share an array). assimp reads an array by its
// count and an accessor by its own count and stride, past the values the file holds: what a short array
// read differed from run to run. Accessors are checked once every array is known (one may come first).
void check_collada_arrays(std::string_view bytes, const std::string& file) {
    static constexpr std::string_view arrays[] = {"float_array", "int_array",    "bool_array", "Name_array",
                                                  "IDREF_array", "SIDREF_array", "token_array"};
    std::unordered_map<std::string, std::size_t> array_values;  // "#id": its count, the smallest of an id's
    std::vector<ColladaAccessor> accessors;
    const auto number = [&](std::string_view tag, std::size_t at, std::string_view attribute,
                            std::size_t fallback) {
        const std::optional<std::string_view> text = xml_attribute(tag, attribute);
        return text ? read_count(*text, file, "byte " + std::to_string(at) + " " + std::string(attribute))
                    : fallback;
    };
    for_each_xml_tag(bytes, [&](std::size_t at, std::string_view tag) {
        const std::string_view name = collada_element(tag);
        const std::size_t end = at + tag.size();
        if (std::find(std::begin(arrays), std::end(arrays), name) != std::end(arrays)) {
            const std::size_t count = number(tag, at, "count", 0);
            std::size_t values = 0;
            const std::string_view content = tag[tag.size() - 2] == '/'
                                                 ? std::string_view()
                                                 : bytes.substr(end, bytes.find('<', end) - end);
            for (std::size_t c = 0; c < content.size(); ++c)
                values += !std::isspace(static_cast<unsigned char>(content[c])) &&
                          (c == 0 || std::isspace(static_cast<unsigned char>(content[c - 1])));
            if (values < count)
                throw_input_error(
                    file, "byte " + std::to_string(at) + " <" + std::string(name) + ">",
                    "count " + std::to_string(count) + " but " + std::to_string(values) + " values");
            if (auto id = xml_attribute(tag, "id")) {
                auto [known, added] = array_values.emplace(std::string(*id).insert(0, 1, '#'), count);
                known->second = std::min(known->second, count);
            }
        } else if (name == "accessor") {
            const std::size_t close = tag[tag.size() - 2] == '/' ? end : bytes.find("accessor>", end);
            const std::string_view inside =
                bytes.substr(end, close == std::string_view::npos ? 0 : close - end);
            std::size_t params = 0;
            for (std::size_t p = inside.find("param"); p != std::string_view::npos;
                 p = inside.find("param", p + 1))
                params += p > 0 && (inside[p - 1] == '<' || inside[p - 1] == ':');
            accessors.push_back({at, std::string(xml_attribute(tag, "source").value_or("")),
                                 number(tag, at, "offset", 0), number(tag, at, "count", 0),
                                 number(tag, at, "stride", 1), std::max<std::size_t>(params, 1)});
        }
    });
    check_collada_accessors(accessors, array_values, file);
}

// COLLADA's node tree with its instance_node references (COLLADA 1.4.1 specification, chapter 5: node,
// instance_node): assimp builds the scene by recursion through every node a node instances (found by its
// id, else its name, anywhere in the file), so nodes that instance each other crashed it.
void check_collada_nodes(std::string_view bytes, const std::string& file) {
    std::vector<std::vector<std::uint32_t>> edges;  // a node's children and the nodes it instances
    std::vector<std::string> places;                // "byte N <node id="a">"
    std::unordered_map<std::string_view, std::uint32_t> ids, names;
    std::vector<std::pair<std::uint32_t, std::string_view>> instances;  // (node, the id it instances)
    std::vector<std::uint32_t> open;
    for_each_xml_tag(bytes, [&](std::size_t at, std::string_view tag) {
        const bool closing = tag[1] == '/';
        const std::string_view name = collada_element(closing ? tag.substr(1) : tag);
        if (name == "node" && closing) {
            if (!open.empty()) open.pop_back();
        } else if (name == "node") {
            const auto node = std::uint32_t(edges.size());
            edges.emplace_back();
            const std::optional<std::string_view> id = xml_attribute(tag, "id");
            places.push_back("byte " + std::to_string(at) + " <node" +
                             (id ? " id=\"" + std::string(id->substr(0, 40)) + "\"" : "") + ">");
            if (!open.empty()) edges[open.back()].push_back(node);
            if (id) ids.emplace(*id, node);
            if (auto node_name = xml_attribute(tag, "name")) names.emplace(*node_name, node);
            if (tag[tag.size() - 2] != '/') open.push_back(node);
        } else if (name == "instance_node" && !open.empty()) {
            const std::string_view url = xml_attribute(tag, "url").value_or("");
            if (!url.empty() && url[0] == '#') instances.emplace_back(open.back(), url.substr(1));
        }
    });
    for (const auto& [node, id] : instances) {
        if (const auto by_id = ids.find(id); by_id != ids.end())
            edges[node].push_back(by_id->second);
        else if (const auto by_name = names.find(id); by_name != names.end())
            edges[node].push_back(by_name->second);
    }
    check_acyclic_and_shallow(
        edges, [&](std::uint32_t node) { return places[node]; }, "nodes with the nodes they instance", file,
        max_nesting_depth);
}

}  // namespace

void check_xml_depth(std::string_view bytes, const std::string& file) {
    int depth = 0;
    for_each_xml_tag(bytes, [&](std::size_t at, std::string_view tag) {
        if (tag[1] == '/') {
            --depth;
            return;
        }
        if (tag[1] != '!' && tag[tag.size() - 2] != '/' && ++depth > max_nesting_depth)
            throw_input_error(file, "byte " + std::to_string(at), "XML elements " + nesting_message());
    });
}

void check_collada_file(std::string_view bytes, const std::string& file) {
    check_xml_depth(bytes, file);
    check_collada_arrays(bytes, file);
    check_collada_nodes(bytes, file);
}

}  // namespace boxlod
