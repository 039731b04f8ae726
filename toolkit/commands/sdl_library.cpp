#include "toolkit/commands/sdl_library.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <type_traits>

namespace boxlod {

namespace {

const char* const library_name = "libSDL2-2.0.so.0";

SdlLibrary load() {
    void* library = ::dlopen(library_name, RTLD_NOW | RTLD_LOCAL);  // kept open for the process
    if (!library)
        throw std::runtime_error(std::string("cannot load SDL2 for the viewer's window: ") + ::dlerror());
    SdlLibrary functions;
    auto find = [&](auto& function, const char* name) {
        function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(::dlsym(library, name));
        if (!function) throw std::runtime_error(std::string(library_name) + " has no " + name);
    };
#define BOXLOD_SDL_FIND(name) find(functions.name, #name);
    BOXLOD_SDL_FUNCTIONS(BOXLOD_SDL_FIND)
#undef BOXLOD_SDL_FIND
    return functions;
}

}  // namespace

const SdlLibrary& sdl() {
    static const SdlLibrary functions = load();
    return functions;
}

}  // namespace boxlod
