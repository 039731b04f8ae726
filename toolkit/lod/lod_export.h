// The files of an LoD export (docs/design.md: Files; the manual's Save Mesh):
// NAME.gltf + NAME.bin, NAME_color_K.png, NAME_normal_K.png, NAME_height_K.png,
// NAME.params.txt, NAME.preview.png, NAME.stats.txt — each written atomically.
#pragma once
#include "renderer/image.h"
#include "toolkit/lod/lod.h"
#include "toolkit/lod/lod_parameters.h"

#include <string>

namespace boxlod {

// A render of the LoD of `original` with the camera, light and render mode of
// `sized`, the parameters it was sized with (chain.h: Chain::sized_parameters;
// without a camera, from +X+Y+Z at their distance).
Image8 render_lod_preview(const Lod& lod, const Model& original, const LodParameters& sized, int width,
                          int height, int threads);

// Renames the LoD's page textures NAME_color_K.png, NAME_normal_K.png, ...
void name_pages(Lod& lod, const std::string& name);

// `lod` by value: its page textures are renamed NAME_color_K.png ... in place;
// move it in when it is not needed afterwards (the pages are large). The
// parameter file saves `chain_parameters` (toolkit/lod/chain/chain.h: Chain::parameters)
// at the level's number, so that building from it makes the same level. `binary`:
// NAME.glb with the pages inside, instead of NAME.gltf + .bin + PNGs.
void export_lod(Lod lod, const LodParameters& chain_parameters, const std::string& directory,
                const std::string& name, const Image8& preview, int threads, bool binary = false);

// Whether export_lod as `name` may write a file of this name (NAME.gltf,
// NAME_color_0.png, ...), or, with `levels`, as NAME_L<c> for some level c:
// a build must not write over the model it reads.
bool lod_export_writes(const std::string& file_name, const std::string& name, bool levels = false);

}  // namespace boxlod
