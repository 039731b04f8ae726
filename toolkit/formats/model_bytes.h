// A model as bytes and back, field for field: how the isolated reader's child
// process hands its scene to boxlod (toolkit/formats/assimp_io.h). Not a file format:
// the bytes live only between two processes of the same build.
#pragma once
#include "toolkit/model/model.h"

#include <string>
#include <string_view>

namespace boxlod {

std::string model_bytes(const Model& model);
// Throws std::logic_error for bytes model_bytes did not write whole.
Model model_from_bytes(std::string_view bytes);

}  // namespace boxlod
