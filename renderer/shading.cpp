#include "renderer/shading.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace boxlod {
namespace {

// The mip level of a fragment depends on a texture only through its size: the
// maps of a baked face share one, and a ray march samples one map many times,
// so it is computed once per size met.
class MipLevels {
public:
    explicit MipLevels(const Fragment& f) : fragment_(f) {}
    float of(const MipTexture& texture) {
        const MipTexture::Level& top = texture.levels[0];
        if (top.width != width_ || top.height != height_) {
            width_ = top.width;
            height_ = top.height;
            level_ = mip_level(texture, fragment_.duv_dx, fragment_.duv_dy);
        }
        return level_;
    }

private:
    const Fragment& fragment_;
    int width_ = -1, height_ = -1;
    float level_ = 0;
};

Eigen::Vector4f sample_surface(const MipTexture& texture, MipLevels& levels, const Eigen::Vector2f& uv) {
    return sample(texture, uv, levels.of(texture));
}

// The unit vector to the eye; two-sided lighting turns the fragment's frame
// towards it, and `turned` says whether it did (the surface is seen from behind).
[[gnu::always_inline]] inline Eigen::Vector3f face_the_viewer(const Eigen::Vector3f& eye, Fragment& f,
                                                              bool& turned) {
    Eigen::Vector3f view = (eye - f.position);
    float view_length = view.norm();
    view = view_length > 0 ? Eigen::Vector3f(view / view_length) : Eigen::Vector3f(0, 0, 1);
    turned = f.geometric_normal.dot(view) < 0;
    if (turned) {
        f.geometric_normal = -f.geometric_normal;
        f.normal = -f.normal;
        f.bitangent = -f.bitangent;
    }
    return view;
}

// Blinn-Phong with the manual's light (ambient + diffuse x albedo, specular x the material's).
[[gnu::always_inline]] inline Eigen::Vector3f blinn_phong(const Light& light, const Surface& s,
                                                          const Fragment& f, const Eigen::Vector3f& view,
                                                          const Eigen::Vector4f& albedo,
                                                          const Eigen::Vector3f& normal) {
    Eigen::Vector3f to_light = (light.position - f.position).normalized();
    Eigen::Vector3f halfway = (to_light + view).normalized();
    float diffuse = std::max(0.0f, normal.dot(to_light));
    float shininess = light.shininess > 0 ? light.shininess : s.shininess;
    float specular = diffuse > 0 ? std::pow(std::max(0.0f, normal.dot(halfway)), shininess) : 0;
    return albedo.head<3>() * (light.ambient + light.diffuse * diffuse) +
           s.specular * (light.specular * specular);
}

// face_the_viewer in lanes: the view vector; `turned` marks the lanes seen from behind.
Vector3Lanes face_the_viewer(const Eigen::Vector3f& eye, const FragmentLanes& f, IntLanes& turned) {
    Vector3Lanes view = broadcast(eye) - f.position;
    FloatLanes view_length = square_root(dot(view, view));
    view = select(view_length > 0, view / view_length,
                  Vector3Lanes{broadcast(0.0f), broadcast(0.0f), broadcast(1.0f)});
    turned = dot(f.geometric_normal, view) < 0;
    return view;
}

// blinn_phong in lanes, each lane with its surface's specular colour and
// shininess; glibc's powf stays per lane, for its bits.
[[gnu::always_inline]] inline Vector3Lanes blinn_phong(const Light& light, const FragmentLanes& f,
                                                       const Vector3Lanes& view, const Vector3Lanes& albedo,
                                                       const Vector3Lanes& specular_color,
                                                       const Vector3Lanes& normal) {
    Vector3Lanes to_light = normalized(broadcast(light.position) - f.position);
    Vector3Lanes halfway = normalized(to_light + view);
    FloatLanes diffuse = max_zero(dot(normal, to_light)), specular_base = max_zero(dot(normal, halfway));
    float specular[lane_count] = {};
    for (int j = 0; j < f.count; ++j) {
        float shininess = light.shininess > 0 ? light.shininess : f.surface[j]->shininess;
        if (diffuse[j] > 0) specular[j] = std::pow(specular_base[j], shininess);
    }
    FloatLanes lit = broadcast(light.ambient) + broadcast(light.diffuse) * diffuse;
    FloatLanes highlight =
        broadcast(light.specular) * from_scalars(specular[0], specular[1], specular[2], specular[3]);
    return {albedo.x * lit + specular_color.x * highlight, albedo.y * lit + specular_color.y * highlight,
            albedo.z * lit + specular_color.z * highlight};
}

bool one_surface(const FragmentLanes& f) {
    return f.surface[1] == f.surface[0] && f.surface[2] == f.surface[0] && f.surface[3] == f.surface[0];
}

// Each lane's surface's base colour (rgb, alpha) and specular colour.
void materials(const FragmentLanes& f, Vector3Lanes& base_color, FloatLanes& base_alpha,
               Vector3Lanes& specular_color) {
    if (one_surface(f)) {
        const Surface& s = *f.surface[0];
        base_color = broadcast(Eigen::Vector3f(s.base_color.head<3>()));
        base_alpha = broadcast(s.base_color.w());
        specular_color = broadcast(s.specular);
        return;
    }
    for (int j = 0; j < lane_count; ++j) {
        const Surface& s = *f.surface[j];
        set_lane(base_color, j, s.base_color.head<3>());
        base_alpha[j] = s.base_color.w();
        set_lane(specular_color, j, s.specular);
    }
}

// Material colour and vertex normals only.
class UntexturedShader : public Shader {
public:
    UntexturedShader(const Light& light, const Eigen::Vector3f& eye) : light_(light), eye_(eye) {}
    bool reads_uv() const override { return false; }
    ShadedPixel shade(const Surface& s, Fragment& f) const override {
        bool turned;
        Eigen::Vector3f view = face_the_viewer(eye_, f, turned);
        return {blinn_phong(light_, s, f, view, s.base_color, f.normal), f.normal, s.base_color.w()};
    }
    // shade() in lanes, operation for operation (face_the_viewer, blinn_phong).
    void shade_lanes(const FragmentLanes& f, ShadedLanes& shaded) const override {
        IntLanes turned;
        const Vector3Lanes view = face_the_viewer(eye_, f, turned);
        const Vector3Lanes normal = select(turned, -f.normal, f.normal);
        Vector3Lanes albedo, specular_color;
        materials(f, albedo, shaded.alpha, specular_color);
        shaded.color = blinn_phong(light_, f, view, albedo, specular_color, normal);
        shaded.normal = normal;
    }

private:
    Light light_;
    Eigen::Vector3f eye_;
};

// Albedo = material colour x colour map, normal from the normal map; lit by
// Blinn-Phong, or unlit (albedo mode: what baking records, the mapped normal too).
class MappedShader : public Shader {
public:
    // `displaces`: a subclass offsets uvs by the height map (displaced_uv).
    MappedShader(const Light& light, const Eigen::Vector3f& eye, bool lit, bool displaces = false)
        : light_(light), eye_(eye), lit_(lit), displaces_(displaces) {}
    bool reads_uv() const override { return true; }
    // shade() in lanes, operation for operation, where each lane either has
    // no maps to read (no uvs, or a surface without maps) or reads colour and
    // normal maps of one layout, and nothing is displaced. Other groups go
    // lane by lane through shade().
    void shade_lanes(const FragmentLanes& f, ShadedLanes& shaded) const override {
        IntLanes mapped{};
        for (int j = 0; j < f.count; ++j) {
            if (!f.has_uv[j]) continue;
            if (j > 0 && f.has_uv[j - 1] && f.surface[j] == f.surface[j - 1]) {  // checked already
                mapped[j] = mapped[j - 1];
                continue;
            }
            const Surface& s = *f.surface[j];
            if ((displaces_ && s.height) || bool(s.color) != bool(s.normal) ||
                (s.color && !same_layout(*s.color, *s.normal)))
                return Shader::shade_lanes(f, shaded);
            mapped[j] = s.color ? -1 : 0;
        }
        IntLanes turned;
        const Vector3Lanes view = face_the_viewer(eye_, f, turned);
        const Vector3Lanes surface_normal = select(turned, -f.normal, f.normal);
        Vector3Lanes albedo, specular_color;
        materials(f, albedo, shaded.alpha, specular_color);
        shaded.normal = surface_normal;
        if (_mm_movemask_ps(__m128(mapped)) != 0) {
            // Lanes without maps read texels of 1 (albedo x 1 is albedo) and keep their normal.
            Vector4Lanes color_texel{broadcast(1.0f), broadcast(1.0f), broadcast(1.0f), broadcast(1.0f)},
                normal_texel{};
            sample_maps(f, mapped, color_texel, normal_texel);
            albedo = {albedo.x * color_texel.x, albedo.y * color_texel.y, albedo.z * color_texel.z};
            shaded.alpha = shaded.alpha * color_texel.w;
            const Vector3Lanes bitangent = select(turned, -f.bitangent, f.bitangent);
            const Vector3Lanes normal = f.tangent * (normal_texel.x * 2 - 1) +
                                        bitangent * (normal_texel.y * 2 - 1) +
                                        surface_normal * (normal_texel.z * 2 - 1);
            const FloatLanes squared = dot(normal, normal);
            shaded.normal = select(mapped & (squared > 0), normal / square_root(squared), surface_normal);
        }
        shaded.color = lit_ ? blinn_phong(light_, f, view, albedo, specular_color, shaded.normal) : albedo;
    }
    ShadedPixel shade(const Surface& s, Fragment& f) const override {
        bool turned;
        Eigen::Vector3f view = face_the_viewer(eye_, f, turned);
        Eigen::Vector4f albedo = s.base_color;
        Eigen::Vector3f normal = f.normal;
        if (f.has_uv) {
            MipLevels levels(f);
            // A metric height map describes what lies behind the surface seen from
            // its front; from behind (inside a box, through cut-out texels) no offset fits.
            const bool displace = s.height && !(turned && s.height_depth > 0);
            Eigen::Vector2f uv = displace ? displaced_uv(s, f, levels, view) : f.uv;
            Eigen::Vector4f color_texel = Eigen::Vector4f::Ones(),
                            normal_texel = Eigen::Vector4f::Zero();  // set where read
            if (s.color && s.normal)
                std::tie(color_texel, normal_texel) =
                    sample_both(*s.color, levels.of(*s.color), *s.normal, levels.of(*s.normal), uv);
            else if (s.color)
                color_texel = sample_surface(*s.color, levels, uv);
            else if (s.normal)
                normal_texel = sample_surface(*s.normal, levels, uv);
            if (s.color) albedo = albedo.cwiseProduct(color_texel);
            if (s.normal) {
                const Eigen::Vector4f& texel = normal_texel;
                Eigen::Vector3f n(texel.x() * 2 - 1, texel.y() * 2 - 1, texel.z() * 2 - 1);
                Eigen::Vector3f mapped = f.tangent * n.x() + f.bitangent * n.y() + f.normal * n.z();
                if (mapped.squaredNorm() > 0) normal = mapped.normalized();
            }
        }
        if (!lit_) return {albedo.head<3>(), normal, albedo.w()};
        return {blinn_phong(light_, s, f, view, albedo, normal), normal, albedo.w()};
    }

private:
    // The colour and normal texels of the `mapped` lanes (shade()'s sample_both).
    static void sample_maps(const FragmentLanes& f, IntLanes mapped, Vector4Lanes& color_texel,
                            Vector4Lanes& normal_texel) {
        const Surface& s = *f.surface[0];
        if (one_surface(f) && _mm_movemask_ps(__m128(mapped)) == (1 << f.count) - 1) {
            const FloatLanes lod = mip_level(*s.color, f.du_dx, f.dv_dx, f.du_dy, f.dv_dy, f.count);
            sample_both(*s.color, *s.normal, f.u, f.v, lod, f.count, color_texel, normal_texel);
            return;
        }
        for (int j = 0; j < f.count; ++j) {
            if (!mapped[j]) continue;
            const Surface& lane_surface = *f.surface[j];
            const float lod =
                mip_level(*lane_surface.color, {f.du_dx[j], f.dv_dx[j]}, {f.du_dy[j], f.dv_dy[j]});
            const auto [color, normal] =
                sample_both(*lane_surface.color, lod, *lane_surface.normal, lod, {f.u[j], f.v[j]});
            color_texel.x[j] = color.x();
            color_texel.y[j] = color.y();
            color_texel.z[j] = color.z();
            color_texel.w[j] = color.w();
            normal_texel.x[j] = normal.x();
            normal_texel.y[j] = normal.y();
            normal_texel.z[j] = normal.z();
        }
    }

protected:
    // Where the maps are sampled: the fragment's uv, or displaced by s's height map.
    virtual Eigen::Vector2f displaced_uv(const Surface&, const Fragment& f, MipLevels&,
                                         const Eigen::Vector3f&) const {
        return f.uv;
    }
    // The view vector in the tangent frame, and the uv offset of the point one
    // unit of depth below the surface on the line of sight, with offset limiting
    // (Welsh 2004): V.xy in uv (v grows down the image, the bitangent points up)
    // where the height map is in uv units (the manual's), the view's component
    // in the surface mapped through the uv gradient and times the depth where the
    // height map states its depth in metres (docs/design.md: Rendering).
    static Eigen::Vector3f tangent_view(const Surface& s, const Fragment& f, const Eigen::Vector3f& view,
                                        Eigen::Vector2f& uv_per_depth) {
        Eigen::Vector3f v(view.dot(f.tangent), view.dot(f.bitangent), view.dot(f.normal));
        if (s.height_depth <= 0)
            uv_per_depth = Eigen::Vector2f(v.x(), -v.y());
        else if (!f.uv_gradient)
            uv_per_depth = Eigen::Vector2f::Zero();  // no uv gradient (degenerate uvs): no offset
        else
            uv_per_depth = Eigen::Vector2f(f.uv_gradient->du_dposition.dot(view),
                                           f.uv_gradient->dv_dposition.dot(view)) *
                           s.height_depth;
        return v;
    }

private:
    Light light_;
    Eigen::Vector3f eye_;
    bool lit_, displaces_;
};

// Parallax mapping with offset limiting (Welsh 2004): offset = (h * scale + bias) * V.xy
// in uv; for a height map with a depth, the exact depth (1 - h) below the surface.
class ParallaxShader : public MappedShader {
public:
    ParallaxShader(const Light& light, const Eigen::Vector3f& eye, float scale, float bias)
        : MappedShader(light, eye, true, true), scale_(scale), bias_(bias) {}

protected:
    Eigen::Vector2f displaced_uv(const Surface& s, const Fragment& f, MipLevels& levels,
                                 const Eigen::Vector3f& view) const override {
        Eigen::Vector2f direction;
        tangent_view(s, f, view, direction);
        float h = sample_surface(*s.height, levels, f.uv).x();
        return f.uv + direction * (s.height_depth > 0 ? h - 1 : h * scale_ + bias_);
    }

private:
    float scale_, bias_;
};

// Parallax occlusion mapping (Tatarchuk 2006): march the view ray down from the
// surface (height 1) in steps; refine linearly between the last two samples.
// The ray crosses `scale` in uv, or the height map's stated depth.
class OcclusionShader : public MappedShader {
public:
    OcclusionShader(const Light& light, const Eigen::Vector3f& eye, float scale)
        : MappedShader(light, eye, true, true), scale_(scale) {}

protected:
    Eigen::Vector2f displaced_uv(const Surface& s, const Fragment& f, MipLevels& levels,
                                 const Eigen::Vector3f& view) const override {
        const MipTexture& height = *s.height;
        Eigen::Vector2f direction;
        Eigen::Vector3f v = tangent_view(s, f, view, direction);
        float cos_view = std::max(v.z(), 0.05f);
        int steps = int(std::lround(8 + 24 * (1 - cos_view)));
        Eigen::Vector2f total = direction / cos_view * (s.height_depth > 0 ? 1 : scale_);
        Eigen::Vector2f step = total / float(steps);
        float layer = 1.0f / float(steps), ray = 1, previous_ray = 1;
        Eigen::Vector2f uv = f.uv, previous_uv = f.uv;
        float h = sample_surface(height, levels, uv).x(), previous_h = h;
        for (int i = 0; i < steps && h < ray; ++i) {
            previous_uv = uv;
            previous_ray = ray;
            previous_h = h;
            uv -= step;
            ray -= layer;
            h = sample_surface(height, levels, uv).x();
        }
        float before = previous_h - previous_ray, after = h - ray;  // sign change between the two samples
        float t = before - after != 0 ? before / (before - after) : 0;
        return previous_uv + (uv - previous_uv) * std::clamp(t, 0.0f, 1.0f);
    }

private:
    float scale_;
};

}  // namespace

Fragment fragment_of(const FragmentLanes& lanes, int j) {
    Fragment f;
    f.position = lane(lanes.position, j);
    f.normal = lane(lanes.normal, j);
    f.geometric_normal = lane(lanes.geometric_normal, j);
    if (!lanes.has_uv[j]) return f;
    f.has_uv = true;
    f.uv = {lanes.u[j], lanes.v[j]};
    f.duv_dx = {lanes.du_dx[j], lanes.dv_dx[j]};
    f.duv_dy = {lanes.du_dy[j], lanes.dv_dy[j]};
    f.tangent = lane(lanes.tangent, j);
    f.bitangent = lane(lanes.bitangent, j);
    f.uv_gradient = lanes.uv_gradient[j];
    return f;
}

void Shader::shade_lanes(const FragmentLanes& fragments, ShadedLanes& shaded) const {
    for (int j = 0; j < fragments.count; ++j) {
        Fragment f = fragment_of(fragments, j);
        ShadedPixel pixel = shade(*fragments.surface[j], f);
        set_lane(shaded.color, j, pixel.color);
        set_lane(shaded.normal, j, pixel.normal);
        shaded.alpha[j] = pixel.alpha;
    }
}

std::unique_ptr<Shader> make_shader(const RenderSettings& settings, const Eigen::Vector3f& eye) {
    switch (settings.mode) {
    case RenderMode::untextured: return std::make_unique<UntexturedShader>(settings.light, eye);
    case RenderMode::normal: return std::make_unique<MappedShader>(settings.light, eye, true);
    case RenderMode::parallax:
        return std::make_unique<ParallaxShader>(settings.light, eye, settings.parallax_scale,
                                                settings.parallax_bias);
    case RenderMode::pom:
        return std::make_unique<OcclusionShader>(settings.light, eye, settings.parallax_scale);
    case RenderMode::albedo: return std::make_unique<MappedShader>(settings.light, eye, false);
    }
    throw std::logic_error("make_shader: unknown render mode");
}

}  // namespace boxlod
