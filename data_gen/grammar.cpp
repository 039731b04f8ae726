#include "data_gen/grammar.h"

#include "base/input_error.h"

namespace boxlod {
namespace {

constexpr EnumEntry<FaceSelector> face_selector_table[] = {
    {FaceSelector::front, "front", "the front face"},
    {FaceSelector::back, "back", "the back face"},
    {FaceSelector::left, "left", "the left face"},
    {FaceSelector::right, "right", "the right face"},
    {FaceSelector::top, "top", "the top face"},
    {FaceSelector::bottom, "bottom", "the bottom face"},
    {FaceSelector::side, "side", "left and right"},
    {FaceSelector::vertical, "vertical", "all but top and bottom"},
    {FaceSelector::horizontal, "horizontal", "top and bottom"},
    {FaceSelector::all, "all", "every face"},
};

constexpr EnumEntry<Operation::Kind> operation_kind_table[] = {
    {Operation::Kind::extrude, "extrude", "extrude([axis,] height)"},
    {Operation::Kind::split, "split", "split(axis) { entries }"},
    {Operation::Kind::component, "comp", "comp(f) { selector : sequence | ... }"},
    {Operation::Kind::translate, "t", "t(x, y, z)"},
    {Operation::Kind::rotate, "r", "r(x, y, z) in degrees"},
    {Operation::Kind::scale, "s", "s(x, y, z)"},
    {Operation::Kind::center, "center", "center(axes)"},
    {Operation::Kind::insert, "i", "i(primitive [, segments]) or i(\"asset file\")"},
    {Operation::Kind::material, "material", "material(name)"},
    {Operation::Kind::texture, "texture", "texture(name)"},
    {Operation::Kind::color, "color", "color(r, g, b) or color(\"#rrggbb\")"},
};

}  // namespace

std::span<const EnumEntry<FaceSelector>> face_selectors() { return face_selector_table; }
std::span<const EnumEntry<Operation::Kind>> operation_kinds() { return operation_kind_table; }

bool selects(FaceSelector selector, const std::string& face) {
    const bool vertical = face != "top" && face != "bottom";
    switch (selector) {
    case FaceSelector::all: return true;
    case FaceSelector::vertical: return vertical;
    case FaceSelector::horizontal: return !vertical;
    case FaceSelector::side: return face == "left" || face == "right";
    default: return face == enum_name(face_selectors(), selector);
    }
}

std::string grammar_message(const std::string& file, SourcePlace place, const std::string& what) {
    std::string message =
        file + ":" + std::to_string(place.line) + ":" + std::to_string(place.column) + ": " + what;
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    return message;
}

void throw_grammar_error(const std::string& file, SourcePlace place, const std::string& what) {
    throw InputError(grammar_message(file, place, what));
}

}  // namespace boxlod
