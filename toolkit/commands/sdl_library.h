// SDL2, loaded when the viewer first needs it (dlopen of libSDL2-2.0.so.0),
// so that every other command starts without SDL's fifty-odd libraries, which
// took most of a process start (docs/performance.md: Image metrics). SDL's
// header gives the types and constants; the functions the viewer calls
// are listed once below and reached as sdl().SDL_Init(...).
#pragma once
#include <SDL.h>

namespace boxlod {

// One table, its names in rows (not one per line, as clang-format would have it).
// clang-format off
#define BOXLOD_SDL_FUNCTIONS(X)                                                                    \
    X(SDL_Init) X(SDL_Quit) X(SDL_GetError) X(SDL_CreateWindow) X(SDL_DestroyWindow)                \
    X(SDL_CreateRenderer) X(SDL_DestroyRenderer) X(SDL_CreateTexture) X(SDL_DestroyTexture)         \
    X(SDL_UpdateTexture) X(SDL_RenderCopy) X(SDL_RenderPresent) X(SDL_PushEvent) X(SDL_PollEvent)   \
    X(SDL_WaitEventTimeout) X(SDL_GetKeyName) X(SDL_GetKeyFromName) X(SDL_GetCurrentVideoDriver)
// clang-format on

struct SdlLibrary {
#define BOXLOD_SDL_MEMBER(name) decltype(&::name) name = nullptr;
    BOXLOD_SDL_FUNCTIONS(BOXLOD_SDL_MEMBER)
#undef BOXLOD_SDL_MEMBER
};

// Loaded on the first call; throws std::runtime_error naming the library when
// it or one of its functions is missing.
const SdlLibrary& sdl();

}  // namespace boxlod
