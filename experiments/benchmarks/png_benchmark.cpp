// Writing LoD textures: boxlod's PNG encoder (libspng, zlib level 2, no row
// filter) against stb_image_write, the encoder boxlod used before, at its
// defaults (level 8, adaptive filters) and at the settings boxlod gave it
// (level 5, no filter), in one run. The pages are the real thing: every page
// of level 8 of the `manual` sample (colour RGBA8, normal RGB8, height 16-bit
// for boxlod; stb writes 8 bits only, so it encodes colour and normal).
//   build/experiments/png_benchmark
// Counters: encoded MB and raw MB encoded per second.
#include "data_gen/interpreter.h"
#include "data_gen/samples.h"
#include "toolkit/lod/chain/chain.h"
#include "toolkit/lod/pages/level_pages.h"

#include <benchmark/benchmark.h>

#include <cstdlib>

// stb_image_write's PNG writer and settings; libstb exports them, its header keeps them private.
extern "C" unsigned char* stbi_write_png_to_mem(const unsigned char* pixels, int stride, int width,
                                                int height, int channels, int* length);
extern "C" int stbi_write_png_compression_level;
extern "C" int stbi_write_force_png_filter;

using namespace boxlod;

namespace {

struct Pages {
    std::vector<const Image8*> images8;    // colour and normal pages
    std::vector<const Image16*> images16;  // height pages
    std::unique_ptr<Lod> lod;
};

const Pages& manual_pages() {
    static const Pages pages = [] {
        Pages p;
        Model model = generate_building(sample_grammar("manual"), BuildingOptions{});
        // The manual's program bakes every box; the default chain keeps cheap sub-trees as meshes
        // and draws small faces flat, which leaves level 8 with few or no pages to write.
        LodParameters parameters;
        set_manual(parameters);
        p.lod = std::make_unique<Lod>(Chain(model, parameters, 0).build(8));
        for (std::size_t page = 0; page < p.lod->atlas.pages.size(); ++page) {
            LodPage textures = lod_page(int(page));
            p.images8.push_back(&p.lod->model.textures[std::size_t(textures.color)].image);
            p.images8.push_back(&p.lod->model.textures[std::size_t(textures.normal)].image);
            p.images16.push_back(&p.lod->model.textures[std::size_t(textures.height)].image16);
        }
        return p;
    }();
    return pages;
}

void count(::benchmark::State& state, std::size_t raw, std::size_t encoded) {
    state.counters["MB"] = double(encoded) * 1e-6;
    state.counters["raw MB/s"] =
        ::benchmark::Counter(double(raw) * 1e-6, ::benchmark::Counter::kIsIterationInvariantRate);
}

// A benchmark of nothing would read as a speed-up: no pages is an error.
bool have_pages(::benchmark::State& state, const Pages& pages) {
    if (!pages.images8.empty()) return true;
    state.SkipWithError("level 8 of manual has no texture pages");
    return false;
}

void boxlod_png(::benchmark::State& state) {
    const Pages& pages = manual_pages();
    if (!have_pages(state, pages)) return;
    std::size_t raw = 0, encoded = 0;
    for (auto _ : state) {
        raw = encoded = 0;
        for (const Image8* image : pages.images8) {
            raw += image->pixels.size();
            encoded += encode_png(*image).size();
        }
        if (state.range(0))
            for (const Image16* image : pages.images16) {
                raw += image->pixels.size() * 2;
                encoded += encode_png16(*image).size();
            }
    }
    count(state, raw, encoded);
}
// Argument 1: with the 16-bit height pages (boxlod's whole page set); 0: colour and normal only, as stb.
BENCHMARK(boxlod_png)->Arg(0)->Arg(1)->Unit(::benchmark::kMillisecond)->UseRealTime()->MinTime(2);

void stb_png(::benchmark::State& state) {
    const Pages& pages = manual_pages();
    if (!have_pages(state, pages)) return;
    stbi_write_png_compression_level = int(state.range(0));
    stbi_write_force_png_filter = int(state.range(1));
    std::size_t raw = 0, encoded = 0;
    for (auto _ : state) {
        raw = encoded = 0;
        for (const Image8* image : pages.images8) {
            int length = 0;
            unsigned char* png = stbi_write_png_to_mem(image->pixels.data(), image->width * image->channels,
                                                       image->width, image->height, image->channels, &length);
            std::free(png);
            raw += image->pixels.size();
            encoded += std::size_t(length);
        }
    }
    count(state, raw, encoded);
}
// (level, filter): stb's defaults (8, -1: adaptive), and what boxlod set (5, 0: none).
BENCHMARK(stb_png)->Args({8, -1})->Args({5, 0})->Unit(::benchmark::kMillisecond)->UseRealTime()->MinTime(2);

}  // namespace

BENCHMARK_MAIN();
