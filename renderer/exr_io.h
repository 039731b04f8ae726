// OpenEXR output: linear half RGBA plus float depth (Z), for analysis
// without 8-bit quantisation.
#pragma once
#include "renderer/camera.h"
#include "renderer/renderer.h"

#include <string>

namespace boxlod {

// Z is the distance along the view direction (view-space depth); +inf where uncovered.
void write_exr(const std::string& path, const Frame& frame, const Camera& camera);  // atomic

// View-space depth from a frame's window depth.
std::vector<float> view_depth(const Frame& frame, const Camera& camera);

}  // namespace boxlod
