// The parameter file (docs/design.md: Parameter file; the manual's Loading and
// Saving Files): plain text, one `key = value` per line, `#` comments. It
// holds the model file, every LoD parameter, the camera and the light.
#pragma once
#include "base/key_values.h"
#include "toolkit/lod/lod_parameters.h"

#include <string>

namespace boxlod {

// Every key in file order, numbers printed so they read back exactly.
KeyValues parameter_entries(const LodParameters& parameters);
std::string format_parameters(const LodParameters& parameters);
// `file` names the source in errors: "file:line: key: what is wrong".
LodParameters parse_parameters(const std::string& text, const std::string& file);
LodParameters load_parameters(const std::string& path);
// Atomic; an absolute model path is written as given, a relative one relative to the file.
void save_parameters(const std::string& path, const LodParameters& parameters);

}  // namespace boxlod
