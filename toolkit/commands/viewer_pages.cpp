#include "toolkit/commands/viewer_pages.h"

#include "base/atomic_write.h"
#include "toolkit/formats/gltf_json.h"

#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace boxlod {

extern const std::string_view chain_three_page,
    chain_babylon_page;  // clients/*.html (cmake/embed_text.cmake)

namespace {

std::string html_attribute(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&')
            out += "&amp;";
        else if (c == '"')
            out += "&quot;";
        else if (c == '<')
            out += "&lt;";
        else
            out += c;
    }
    return out;
}

// The page with <meta name="boxlod-chain">, which it opens when no ?file= is given.
std::string page_for(std::string_view page, const std::string& chain_file) {
    const std::string_view charset = "<meta charset=\"utf-8\">";
    const std::size_t at = page.find(charset);
    if (at == std::string_view::npos) throw std::logic_error("a viewer page lost its charset line");
    return std::string(page.substr(0, at + charset.size())) + "\n<meta name=\"boxlod-chain\" content=\"" +
           html_attribute(chain_file) + "\">" + std::string(page.substr(at + charset.size()));
}

}  // namespace

std::vector<std::string> write_viewer_pages(const std::string& chain_path) {
    const std::filesystem::path chain(chain_path);
    const std::string file = chain.filename().string();
    std::vector<std::string> written;
    for (auto [client, page] :
         {std::pair{"three", chain_three_page}, std::pair{"babylon", chain_babylon_page}}) {
        const std::string path =
            (chain.parent_path() / (chain.stem().string() + "." + client + ".html")).string();
        write_text_atomically(path, page_for(page, file_uri(file)));  // a URL: "my house.glb" encoded
        written.push_back(path);
    }
    return written;
}

}  // namespace boxlod
