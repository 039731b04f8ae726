#include "toolkit/formats/cityjson_semantic_colours.h"

namespace boxlod {

namespace {

struct SemanticColour {
    const char* type;
    Eigen::Vector3f colour;
};
const SemanticColour semantic_colours[] = {
    {"RoofSurface", {0.50f, 0.12f, 0.08f}},
    {"WallSurface", {0.75f, 0.72f, 0.65f}},
    {"GroundSurface", {0.20f, 0.20f, 0.20f}},
    {"ClosureSurface", {0.60f, 0.60f, 0.60f}},
    {"OuterCeilingSurface", {0.55f, 0.55f, 0.55f}},
    {"OuterFloorSurface", {0.45f, 0.45f, 0.45f}},
    {"Window", {0.15f, 0.25f, 0.40f}},
    {"Door", {0.30f, 0.17f, 0.08f}},
};
const Eigen::Vector3f unnamed_colour{0.65f, 0.65f, 0.65f};

}  // namespace

Eigen::Vector3f semantic_colour(const std::string& type) {
    for (const SemanticColour& entry : semantic_colours)
        if (type == entry.type) return entry.colour;
    return unnamed_colour;
}

}  // namespace boxlod
