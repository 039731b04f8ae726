// Camera paths for fly-throughs (`boxlod city --path`): keyframes read from a
// file and interpolated, or the built-in `orbit` and `street` paths of a
// generated city. A path is sampled into one pose (eye + target) per frame.
#pragma once
#include "data_gen/city.h"
#include "toolkit/model/model.h"

#include <string>
#include <vector>

namespace boxlod {

struct CameraPose {
    Eigen::Vector3f eye = Eigen::Vector3f::Zero(), target = Eigen::Vector3f::UnitZ();
};

struct Keyframe {
    double time = 0;
    CameraPose pose;
};

// Plain text, one keyframe per line: `time x y z tx ty tz` (eye and target in
// metres), `#` comments and blank lines ignored; times strictly increasing.
// Throws InputError "file: line N: what is wrong" (or "file: what" for no keyframes).
std::vector<Keyframe> parse_keyframes(const std::string& text, const std::string& file);
std::vector<Keyframe> load_keyframes(const std::string& path);

// Eye and target each on a Catmull-Rom spline through the keys, parametrised by
// time (cubic Hermite segments with tangents (p[i+1] - p[i-1]) / (t[i+1] - t[i-1]),
// one-sided at the ends): the path passes through every key at its time and is
// smooth in between. Times outside the keys clamp to the first or last.
CameraPose pose_at(const std::vector<Keyframe>& keys, double time);
// `frames` poses at times spaced evenly from the first key to the last (both included;
// one frame: the first key).
std::vector<CameraPose> sample_keyframes(const std::vector<Keyframe>& keys, int frames);

// A full turn around `center` on a horizontal circle of `radius` at `height` above it,
// always looking at `center`; frame k at angle 2 pi k / frames (the last frame does not
// repeat the first).
std::vector<CameraPose> orbit_path(const Eigen::Vector3f& center, float radius, float height, int frames);

// From `start` to `end` (both included) at constant speed, looking ahead along the line.
std::vector<CameraPose> line_path(const Eigen::Vector3f& start, const Eigen::Vector3f& end, int frames);

// The built-in paths of a planned city (data_gen/city.h) whose buildings and
// streets fill `bounds`, for a camera
// with `fovy_degrees`: `orbit` circles the city at the distance that frames it, 30
// degrees above the horizon, looking at its centre; `street` walks at eye height (2 m)
// down the first street along x with lots on both sides (the first one if there is only
// one row), end to end, looking ahead (not in a city read from a file). Throws
// InputError for another name, as check_city_path does before anything is built.
void check_city_path(const std::string& name, const CityPlan& city);
std::vector<CameraPose> city_path(const std::string& name, const CityPlan& city, const Bounds& bounds,
                                  float fovy_degrees, int frames);

}  // namespace boxlod
