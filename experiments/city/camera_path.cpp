#include "experiments/city/camera_path.h"

#include "base/input_error.h"
#include "base/input_file.h"
#include "base/number_text.h"
#include "renderer/camera.h"
#include "toolkit/model/framing.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace boxlod {
namespace {

// Cubic Hermite between p0 (at t0) and p1 (at t1) with tangents m0, m1 (per unit time).
Eigen::Vector3d hermite(const Eigen::Vector3d& p0, const Eigen::Vector3d& m0, const Eigen::Vector3d& p1,
                        const Eigen::Vector3d& m1, double t0, double t1, double t) {
    double h = t1 - t0, s = (t - t0) / h, s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * p1 +
           (s3 - s2) * h * m1;
}

// Catmull-Rom on one of the pose's points (eye or target) in segment [i, i + 1].
Eigen::Vector3f spline(const std::vector<Keyframe>& keys, std::size_t i, double time,
                       Eigen::Vector3f CameraPose::*point) {
    auto p = [&](std::size_t k) -> Eigen::Vector3d { return (keys[k].pose.*point).cast<double>(); };
    auto tangent = [&](std::size_t k) -> Eigen::Vector3d {
        std::size_t a = k == 0 ? 0 : k - 1, b = std::min(k + 1, keys.size() - 1);
        return (p(b) - p(a)) / (keys[b].time - keys[a].time);
    };
    Eigen::Vector3d value =
        hermite(p(i), tangent(i), p(i + 1), tangent(i + 1), keys[i].time, keys[i + 1].time, time);
    return value.cast<float>();
}

double parse_field(const std::string& word, const std::string& file, int line) {
    const auto value = finite_number<double>(word);
    if (!value)
        throw_input_error(file, "line " + std::to_string(line), "expected a number, got '" + word + "'");
    return *value;
}

std::vector<CameraPose> street_path(const CityPlan& city, int frames) {
    const int rows = city_rows(city);
    const Eigen::Vector3f street = street_along_x(city, rows >= 2 ? 1 : 0);
    const float half_width = city.size.x() / 2, eye_height = 2;
    Eigen::Vector3f start = street + Eigen::Vector3f(-half_width, eye_height, 0);
    Eigen::Vector3f end = street + Eigen::Vector3f(half_width, eye_height, 0);
    return line_path(start, end, frames);
}

}  // namespace

std::vector<Keyframe> parse_keyframes(const std::string& text, const std::string& file) {
    std::vector<Keyframe> keys;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::vector<std::string> fields;
        for (std::string word; words >> word;) fields.push_back(word);
        if (fields.empty()) continue;
        std::string place = "line " + std::to_string(number);
        if (fields.size() != 7)
            throw_input_error(
                file, place,
                "expected 'time x y z tx ty tz' (7 numbers), got " + std::to_string(fields.size()));
        double v[7];
        for (int i = 0; i < 7; ++i) v[i] = parse_field(fields[std::size_t(i)], file, number);
        Keyframe key;
        key.time = v[0];
        key.pose.eye = Eigen::Vector3d(v[1], v[2], v[3]).cast<float>();
        key.pose.target = Eigen::Vector3d(v[4], v[5], v[6]).cast<float>();
        if (!key.pose.eye.allFinite() || !key.pose.target.allFinite())
            throw_input_error(file, place, "a coordinate is too large");
        if (key.pose.eye == key.pose.target)
            throw_input_error(file, place, "the eye and the target coincide");
        if (!keys.empty() && !(key.time > keys.back().time))
            throw_input_error(file, place,
                              "times must increase strictly (" + fields[0] + " after " +
                                  std::to_string(keys.back().time) + ")");
        keys.push_back(key);
    }
    if (keys.empty()) throw_input_error(file, "", "no keyframes (lines 'time x y z tx ty tz')");
    return keys;
}

std::vector<Keyframe> load_keyframes(const std::string& path) {
    return parse_keyframes(read_input_file(path, "keyframe file"), path);
}

CameraPose pose_at(const std::vector<Keyframe>& keys, double time) {
    if (keys.empty()) throw std::invalid_argument("pose_at: no keyframes");
    if (keys.size() == 1 || !(time > keys.front().time)) return keys.front().pose;
    if (time >= keys.back().time) return keys.back().pose;
    std::size_t segment =
        std::size_t(std::upper_bound(keys.begin(), keys.end(), time,
                                     [](double t, const Keyframe& k) { return t < k.time; }) -
                    keys.begin()) -
        1;
    if (time == keys[segment].time) return keys[segment].pose;  // exactly through the keys
    CameraPose pose;
    pose.eye = spline(keys, segment, time, &CameraPose::eye);
    pose.target = spline(keys, segment, time, &CameraPose::target);
    return pose;
}

std::vector<CameraPose> sample_keyframes(const std::vector<Keyframe>& keys, int frames) {
    std::vector<CameraPose> poses;
    double t0 = keys.front().time, t1 = keys.back().time;
    for (int k = 0; k < frames; ++k)
        poses.push_back(
            pose_at(keys, k == frames - 1 && k > 0 ? t1 : t0 + (t1 - t0) * k / std::max(1, frames - 1)));
    return poses;
}

std::vector<CameraPose> orbit_path(const Eigen::Vector3f& center, float radius, float height, int frames) {
    std::vector<CameraPose> poses;
    for (int k = 0; k < frames; ++k) {
        double angle = 2 * M_PI * k / frames;
        CameraPose pose;
        pose.eye = center +
                   Eigen::Vector3d(radius * std::cos(angle), height, radius * std::sin(angle)).cast<float>();
        pose.target = center;
        poses.push_back(pose);
    }
    return poses;
}

std::vector<CameraPose> line_path(const Eigen::Vector3f& start, const Eigen::Vector3f& end, int frames) {
    std::vector<CameraPose> poses;
    Eigen::Vector3f ahead = end - start;
    for (int k = 0; k < frames; ++k) {
        float s = frames > 1 ? float(k) / float(frames - 1) : 0;
        CameraPose pose;
        pose.eye = k == frames - 1 ? end : Eigen::Vector3f(start + ahead * s);
        pose.target = pose.eye + ahead;
        poses.push_back(pose);
    }
    return poses;
}

void check_city_path(const std::string& name, const CityPlan& city) {
    if (name == "street" && !city.given_designs.empty())
        throw InputError(
            "--path street: a city read from a file has no streets of boxlod's grid (orbit, or a keyframe "
            "file)");
    if (name != "street" && name != "orbit")
        throw InputError("--path: unknown built-in path '" + name + "' (orbit, street, or a keyframe file)");
}

std::vector<CameraPose> city_path(const std::string& name, const CityPlan& city, const Bounds& bounds,
                                  float fovy_degrees, int frames) {
    check_city_path(name, city);
    if (name == "street") return street_path(city, frames);
    const Framing framing = framing_of(bounds);
    float distance = framing_distance(framing, fovy_degrees);
    const double elevation = M_PI / 6;  // 30 degrees above the horizon
    return orbit_path(framing.center, float(distance * std::cos(elevation)),
                      float(distance * std::sin(elevation)), frames);
}

}  // namespace boxlod
