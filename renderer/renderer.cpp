// The pipeline (docs/design.md: Rendering): vertex stage, clipping and set-up,
// binning to tiles, a visibility buffer per tile, then one Fragment per visible
// pixel handed to the Shader by the fragment stage (renderer/fragment_stage.h).
#include "renderer/renderer.h"

#include "base/memory_budget.h"
#include "base/parallel.h"
#include "renderer/fragment_stage.h"
#include "renderer/shading.h"

#include <immintrin.h>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace boxlod {

Frame make_frame(int width, int height, const Eigen::Vector3f& background) {
    constexpr double frame_bytes_per_pixel =
        sizeof(Eigen::Vector4f) + sizeof(float) + sizeof(Eigen::Vector3f);
    const double bytes = frame_bytes_per_pixel * double(width) * double(height);
    // The message only when refused: small frames are made by the thousand (hybrid.h).
    if (bytes + held_memory() > memory_budget())
        check_memory("a " + std::to_string(width) + " x " + std::to_string(height) + " frame", bytes);
    Frame frame;
    frame.width = width;
    frame.height = height;
    std::size_t n = std::size_t(width) * height;
    frame.color.assign(n, Eigen::Vector4f(background.x(), background.y(), background.z(), 0));
    frame.depth.assign(n, std::numeric_limits<float>::infinity());
    frame.normal.assign(n, Eigen::Vector3f::Zero());
    return frame;
}

double render_memory(int width, int height) { return 40.0 * double(width) * double(height); }

namespace {

using namespace pipeline;

constexpr std::size_t triangles_per_chunk = 1 << 15;

struct Tiling {
    int columns, rows;
    int count() const { return columns * rows; }
};

// The tiles each of the chunk's triangles from `first` on touches (a range
// of columns and rows; empty when it has no pixel), and how many triangles
// each tile gets: run on each block of triangles right after its set-up,
// while they are in cache.
void count_tiles(Chunk& chunk, std::size_t first, const Tiling& tiling, const Viewport& viewport) {
    const std::size_t end = chunk.triangles.size();
    chunk.tiles_of.resize(end);
    // Locals: stores through them cannot make the compiler reload the vectors.
    const ScreenTriangle* const triangles = chunk.triangles.data();
    TileRange* const tiles_of = chunk.tiles_of.data();
    std::uint32_t* const counts = chunk.tile_counts.data();
    for (std::size_t i = first; i < end; ++i) {
        int x0, y0, x1, y1;
        TileRange& tiles = tiles_of[i];
        if (!triangle_pixel_bounds(triangles[i], viewport, x0, y0, x1, y1)) {
            tiles = {1, 0, 0, 0};
            continue;
        }
        // Bounds are >= 0: a shift divides.
        tiles = {x0 >> tile_bits, y0 >> tile_bits, x1 >> tile_bits, y1 >> tile_bits};
        for (int row = tiles.y0; row <= tiles.y1; ++row)
            for (int column = tiles.x0; column <= tiles.x1; ++column) ++counts[row * tiling.columns + column];
    }
}

// Sorts the chunk's triangles into the tiles they touch, as counted by
// count_tiles, so that each tile's bin keeps submission order.
void fill_bins(Chunk& chunk, const Tiling& tiling) {
    chunk.bin_start.assign(tiling.count() + 1, 0);
    for (int tile = 0; tile < tiling.count(); ++tile)
        chunk.bin_start[tile + 1] = chunk.bin_start[tile] + chunk.tile_counts[tile];
    chunk.bin_items.resize(chunk.bin_start.back());
    std::uint32_t* const next = chunk.tile_counts.data();  // from now on each bin's next slot
    std::copy(chunk.bin_start.begin(), chunk.bin_start.end() - 1, next);
    std::uint32_t* const items = chunk.bin_items.data();
    const TileRange* const tiles_of = chunk.tiles_of.data();
    for (std::size_t i = 0; i < chunk.tiles_of.size(); ++i) {
        const TileRange tiles = tiles_of[i];
        for (int row = tiles.y0; row <= tiles.y1; ++row)
            for (int column = tiles.x0; column <= tiles.x1; ++column)
                items[next[row * tiling.columns + column]++] = std::uint32_t(i);
    }
}

// Blended triangles over the resolved tile, back to front by their mean window
// depth (ties by submission): one global order, so every tile and thread count
// composites alike. Each is depth-tested against the opaque surfaces and
// composited source-over (Porter and Duff 1984): c = a c_src + (1 - a) c_dst,
// coverage a + (1 - a) a_dst. Intersecting or cyclic glass is as good as that
// order, as in engines that sort transparent draws.
template <typename Shade>
void composite_blended(const Context& c, std::vector<std::uint32_t>& blended, const TileTarget& opaque,
                       Frame& frame, const Shade& shade) {
    auto mean_depth = [&](std::uint32_t id) {
        const std::vector<ClippedWeights>* weights;
        const ScreenTriangle& t = triangle_of(c, id, weights);
        return t.z[0] + t.z[1] + t.z[2];
    };
    std::sort(blended.begin(), blended.end(), [&](std::uint32_t a, std::uint32_t b) {
        float za = mean_depth(a), zb = mean_depth(b);
        return za != zb ? za > zb : a < b;
    });
    for (std::uint32_t id : blended) {
        TriangleSetup setup;
        set_up_triangle(c, id, setup);
        visit_triangle(*setup.screen, opaque, [&](int x, int y, float depth) {
            ShadedPixel shaded = shade(setup, x, y);
            float a = std::clamp(shaded.alpha, 0.0f, 1.0f);
            std::size_t pixel = std::size_t(y) * frame.width + x;
            Eigen::Vector4f& color = frame.color[pixel];
            color.head<3>() = shaded.color * a + color.head<3>() * (1 - a);
            color.w() += a * (1 - color.w());
            if (depth < frame.depth[pixel]) {
                frame.depth[pixel] = depth;
                frame.normal[pixel] = shaded.normal;
            }
        });
    }
}

// The tile's shaded pixels (`color`, `normal`, row stride tile.stride) into the
// frame. Unless the tile will read them again (to blend over them), with
// streaming stores, in one pass at the tile's end: a 1080p frame (66 MB) is
// far larger than the caches, an ordinary store first reads the line it
// writes, and streamed stores made one at a time while shading held the
// buffers that texture reads wait for (docs/performance.md: Streaming stores).
void write_tile(const TileTarget& tile, const Eigen::Vector3f* color, const Eigen::Vector3f* normal,
                bool streaming, Frame& frame) {
    auto stream = [](float* to, float value) {
        std::int32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        _mm_stream_si32(reinterpret_cast<int*>(to), bits);
    };
    static_assert(alignof(Eigen::Vector4f) == 16);  // each colour one aligned 16-byte store
    const int width = tile.x1 - tile.x0;
    for (int y = tile.y0; y < tile.y1; ++y) {
        // Row pointers, so the stores cannot make the compiler reload them.
        const std::size_t first = std::size_t(y) * frame.width + tile.x0;
        Eigen::Vector4f* const color_row = frame.color.data() + first;
        float* const depth_row = frame.depth.data() + first;
        Eigen::Vector3f* const normal_row = frame.normal.data() + first;
        const int row = (y - tile.y0) * tile.stride;
        for (int x = 0; x < width; ++x) {
            const int k = row + x;
            if (tile.id[k] == no_triangle) continue;
            if (!streaming) {
                color_row[x] = Eigen::Vector4f(color[k].x(), color[k].y(), color[k].z(), 1);
                depth_row[x] = tile.depth[k];
                normal_row[x] = normal[k];
                continue;
            }
            _mm_stream_ps(color_row[x].data(), _mm_setr_ps(color[k].x(), color[k].y(), color[k].z(), 1.0f));
            stream(depth_row + x, tile.depth[k]);
            for (int i = 0; i < 3; ++i) stream(normal_row[x].data() + i, normal[k][i]);
        }
    }
    _mm_sfence();  // streamed stores are weakly ordered: done before another thread reads the frame
}

// The pixels of tile `tile` within the viewport and its scissor (empty: x0 >= x1 or y0 >= y1).
TileTarget tile_pixels(const Tiling& tiling, int tile, const Viewport& viewport) {
    int x0 = (tile % tiling.columns) * tile_size, y0 = (tile / tiling.columns) * tile_size;
    int x1 = std::min(x0 + tile_size, viewport.width), y1 = std::min(y0 + tile_size, viewport.height);
    x0 = std::max(x0, viewport.scissor_x0);
    y0 = std::max(y0, viewport.scissor_y0);
    x1 = std::min(x1, viewport.scissor_x1);
    y1 = std::min(y1, viewport.scissor_y1);
    return {x0, y0, x1, y1, tile_size, nullptr, nullptr};
}

bool has_triangles(const Context& c, int tile) {
    for (std::size_t chunk_index = 0; chunk_index < c.chunk_count; ++chunk_index)
        if (c.chunks[chunk_index].bin_start[tile + 1] > c.chunks[chunk_index].bin_start[tile]) return true;
    return false;
}

// The visibility buffer: depths from infinity (or the frame's, when asked),
// then the opaque and masked triangles in submission order. Returns the
// blended triangles, which are composited after shading.
std::vector<std::uint32_t> find_visible(const Context& c, int tile, const TileTarget& target,
                                        const Frame& frame) {
    std::fill(target.depth, target.depth + tile_size * tile_size, std::numeric_limits<float>::infinity());
    if (c.settings.depth_from_frame)
        for (int y = target.y0; y < target.y1; ++y)
            std::copy_n(&frame.depth[std::size_t(y) * std::size_t(frame.width) + std::size_t(target.x0)],
                        target.x1 - target.x0, &target.depth[(y - target.y0) * tile_size]);
    std::fill(target.id, target.id + tile_size * tile_size, no_triangle);
    std::vector<std::uint32_t> blended;
    for (std::size_t chunk_index = 0; chunk_index < c.chunk_count; ++chunk_index) {
        const Chunk& chunk = c.chunks[chunk_index];
        for (std::uint32_t k = chunk.bin_start[tile]; k < chunk.bin_start[tile + 1]; ++k) {
            std::uint32_t i = chunk.bin_items[k];
            const ScreenTriangle& t = chunk.triangles[i];
            std::uint32_t id = std::uint32_t(chunk_index << chunk_index_bits) | i;
            const Batch& batch = c.batches[t.batch];
            const Surface& surface = batch.surface;
            if (surface.alpha_mode == AlphaMode::blend) {
                blended.push_back(id);
                continue;
            }
            bool textured_mask =
                surface.alpha_mode == AlphaMode::mask && surface.color && !batch.mesh->uvs.empty();
            if (surface.alpha_mode == AlphaMode::mask && !textured_mask &&
                surface.base_color.w() < surface.alpha_cutoff)
                continue;
            if (!textured_mask) {
                rasterize_triangle(t, id, target, nullptr);
                continue;
            }
            const BarycentricSetup barycentrics = barycentric_setup(t, chunk.weights);
            FragmentTest keep = [&](const ScreenTriangle& tri, int x, int y) {
                const Mesh& mesh = *batch.mesh;
                Eigen::Vector3f b = source_barycentrics(barycentrics, x + 0.5, y + 0.5);
                Eigen::Vector2f uv = interpolate(mesh.uvs, &mesh.indices[std::size_t(tri.triangle) * 3], b);
                return surface.base_color.w() * sample(*surface.color, uv).w() >= surface.alpha_cutoff;
            };
            rasterize_triangle(t, id, target, &keep);
        }
    }
    return blended;
}

// One tile, start to end: visibility, shading, the write into the frame,
// and the blended triangles over it. An empty tile (sky, background) writes nothing.
void render_tile(const Context& c, const Tiling& tiling, int tile, Frame& frame, const Viewport& viewport) {
    TileTarget target = tile_pixels(tiling, tile, viewport);
    if (target.x0 >= target.x1 || target.y0 >= target.y1 || !has_triangles(c, tile)) return;
    float depth[tile_size * tile_size];
    std::uint32_t ids[tile_size * tile_size];
    target.depth = depth;
    target.id = ids;
    std::vector<std::uint32_t> blended = find_visible(c, tile, target, frame);
    ShadedTile shaded;
    shade_tile(c, target, shaded);
    write_tile(target, shaded.color, shaded.normal, blended.empty(), frame);
    if (!blended.empty()) {
        const bool reads_uv = c.shader.reads_uv();
        composite_blended(c, blended, target, frame, [&](const TriangleSetup& setup, int x, int y) {
            return shade_pixel(c, setup, x, y, reads_uv);
        });
    }
}

}  // namespace

namespace {

// A batch's vertices or triangles [begin, end): the unit of parallel work.
struct Range {
    std::size_t batch, begin, end;
};
// A chunk's triangles: consecutive ranges, so that many small batches (a city's
// buildings) share chunks instead of running out of chunk ids.
using ChunkRanges = std::vector<Range>;
constexpr std::size_t chunk_fill = 1 << 12;  // a chunk takes more ranges while it holds fewer triangles
static_assert(7 * (triangles_per_chunk + chunk_fill) < (std::size_t(1) << pipeline::chunk_index_bits));

Viewport viewport_of(const Frame& frame, const RenderSettings& settings) {
    Viewport viewport;
    viewport.width = frame.width;
    viewport.height = frame.height;
    viewport.scissor_x0 = std::max(0, settings.scissor_x0);
    viewport.scissor_y0 = std::max(0, settings.scissor_y0);
    viewport.scissor_x1 = std::min(frame.width, settings.scissor_x1);
    viewport.scissor_y1 = std::min(frame.height, settings.scissor_y1);
    return viewport;
}

// Each batch's object-to-clip matrix: the view-projection, times its
// translation where it has one (columns 0-2 stay exactly the same).
void batch_to_clip(const std::vector<Batch>& batches, const Eigen::Matrix4f& view_projection,
                   std::vector<Eigen::Matrix4f>& to_clip) {
    to_clip.assign(batches.size(), view_projection);
    for (std::size_t b = 0; b < batches.size(); ++b)
        if (!batches[b].translation.isZero(0))
            to_clip[b].col(3) = clip_position(view_projection, batches[b].translation);
}

// Vertex stage: clip-space positions, outcodes and snapped window positions,
// in parallel over vertex ranges. Returns the triangle ranges of each chunk.
std::vector<ChunkRanges> project_vertices(const std::vector<Batch>& batches,
                                          const std::vector<Eigen::Matrix4f>& to_clip,
                                          const Viewport& viewport, int threads,
                                          std::vector<std::vector<ProjectedVertex>>& projected) {
    projected.resize(std::max(projected.size(), batches.size()));
    std::vector<Range> vertex_ranges;
    std::vector<ChunkRanges> chunk_ranges;
    std::size_t filled = chunk_fill;  // triangles in the last chunk
    for (std::size_t b = 0; b < batches.size(); ++b) {
        projected[b].resize(batches[b].mesh->positions.size());
        for (std::size_t i = 0; i < projected[b].size(); i += triangles_per_chunk)
            vertex_ranges.push_back({b, i, std::min(projected[b].size(), i + triangles_per_chunk)});
        std::size_t triangles = batches[b].mesh->indices.size() / 3;
        for (std::size_t i = 0; i < triangles; i += triangles_per_chunk) {
            const Range range{b, i, std::min(triangles, i + triangles_per_chunk)};
            if (filled >= chunk_fill) {
                chunk_ranges.emplace_back();
                filled = 0;
            }
            chunk_ranges.back().push_back(range);
            filled += range.end - range.begin;
        }
    }
    if (chunk_ranges.size() >= (std::size_t(1) << (32 - pipeline::chunk_index_bits)))
        throw std::length_error("render: more triangles than a frame's triangle ids can name");
    parallel_for(vertex_ranges.size(), threads, [&](std::size_t r) {
        const Range& range = vertex_ranges[r];
        const auto& positions = batches[range.batch].mesh->positions;
        const Eigen::Matrix4f& matrix = to_clip[range.batch];
        for (std::size_t i = range.begin; i < range.end; ++i)
            projected[range.batch][i] = project_vertex(clip_position(matrix, positions[i]), viewport);
    });
    return chunk_ranges;
}

// Set-up and binning, in parallel over chunks of triangles, each in blocks
// binned while their screen triangles are still in cache.
void bin_triangles(const std::vector<Batch>& batches, const std::vector<ChunkRanges>& chunk_ranges,
                   const std::vector<std::vector<ProjectedVertex>>& projected,
                   const std::vector<Eigen::Matrix4f>& to_clip, const RenderSettings& settings,
                   const Viewport& viewport, const Tiling& tiling, int threads, std::vector<Chunk>& chunks) {
    if (chunks.size() < chunk_ranges.size()) chunks.resize(chunk_ranges.size());
    for (std::size_t c = 0; c < chunk_ranges.size(); ++c) {
        chunks[c].triangles.clear();
        chunks[c].weights.clear();
    }
    parallel_for(chunk_ranges.size(), threads, [&](std::size_t r) {
        Chunk& chunk = chunks[r];
        chunk.tile_counts.assign(std::size_t(tiling.count()), 0);
        for (const Range& range : chunk_ranges[r]) {
            const Mesh& mesh = *batches[range.batch].mesh;
            const ProjectedMesh projected_mesh{mesh.indices.data(), projected[range.batch].data(),
                                               mesh.positions.data(), &to_clip[range.batch]};
            constexpr std::size_t block = 1024;
            for (std::size_t begin = range.begin; begin < range.end; begin += block) {
                const std::size_t first = chunk.triangles.size();
                setup_triangles(projected_mesh, begin, std::min(range.end, begin + block),
                                std::uint32_t(range.batch), settings.culling, viewport, chunk.triangles,
                                chunk.weights);
                count_tiles(chunk, first, tiling, viewport);
            }
        }
        fill_bins(chunk, tiling);
    });
}

// Where shading sees the eye: an orthographic view has parallel view rays,
// so its "eye" lies far back along them.
Eigen::Vector3f shading_eye(const Camera& camera) {
    if (!camera.orthographic) return camera.position;
    Eigen::Vector3f forward = (camera.target - camera.position).normalized();
    return camera.position - forward * 1e6f;
}

}  // namespace

void render(const std::vector<Batch>& batches, const RenderSettings& settings, Frame& frame) {
    const Viewport viewport = viewport_of(frame, settings);
    const int threads = thread_count(settings.threads);
    const Eigen::Matrix4f view_projection =
        projection_matrix(settings.camera, float(frame.width) / float(frame.height)) *
        view_matrix(settings.camera);
    // Scratch kept per calling thread: a frame of a million triangles needs
    // ~100 MB, and fresh allocations every frame cost more in page faults than
    // the rasterization itself (docs/performance.md: Rasterizer vs Mesa llvmpipe).
    thread_local std::vector<std::vector<ProjectedVertex>> projected;
    thread_local std::vector<Chunk> chunks;
    thread_local std::vector<Eigen::Matrix4f> to_clip;
    batch_to_clip(batches, view_projection, to_clip);
    const std::vector<ChunkRanges> chunk_ranges =
        project_vertices(batches, to_clip, viewport, threads, projected);
    const Tiling tiling{(frame.width + tile_size - 1) / tile_size,
                        (frame.height + tile_size - 1) / tile_size};
    bin_triangles(batches, chunk_ranges, projected, to_clip, settings, viewport, tiling, threads, chunks);

    // Tiles: each owned by one thread; triangles replayed in submission order.
    std::unique_ptr<Shader> mode_shader =
        settings.shader ? nullptr : make_shader(settings, shading_eye(settings.camera));
    const bool translated =
        std::any_of(batches.begin(), batches.end(), [](const Batch& b) { return !b.translation.isZero(0); });
    Context context{
        batches,   settings, chunks, chunk_ranges.size(), settings.shader ? *settings.shader : *mode_shader,
        translated};
    parallel_for(std::size_t(tiling.count()), threads,
                 [&](std::size_t tile) { render_tile(context, tiling, int(tile), frame, viewport); });
}

Image8 frame_to_srgb8(const Frame& frame) {
    Image8 image(frame.width, frame.height, 3);
    for (std::size_t i = 0; i < frame.color.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i * 3 + c] = linear_to_srgb(frame.color[i][c]);
    return image;
}

Frame downsample(const Frame& frame, int factor) {
    if (factor < 1 || frame.width % factor != 0 || frame.height % factor != 0)
        throw std::invalid_argument("downsample: a factor of " + std::to_string(factor) + " for a " +
                                    std::to_string(frame.width) + " x " + std::to_string(frame.height) +
                                    " frame (it must divide both sides)");
    Frame out;
    out.width = frame.width / factor;
    out.height = frame.height / factor;
    out.color.assign(std::size_t(out.width) * std::size_t(out.height), Eigen::Vector4f::Zero());
    const float weight = float(factor * factor);
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x)
            out.color[std::size_t(y / factor) * std::size_t(out.width) + std::size_t(x / factor)] +=
                frame.color[std::size_t(y) * std::size_t(frame.width) + std::size_t(x)] / weight;
    return out;
}

Image8 coverage_mask(const Frame& frame) {
    Image8 mask(frame.width, frame.height, 1);
    for (std::size_t i = 0; i < frame.color.size(); ++i) mask.pixels[i] = frame.color[i].w() > 0 ? 255 : 0;
    return mask;
}

}  // namespace boxlod
