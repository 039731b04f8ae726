#include "toolkit/commands/viewer_pages.h"

#include "test_support.h"

#include <gtest/gtest.h>

using namespace boxlod;

// The pages open the chain beside them by a URL: its file name percent-encoded,
// or a browser would ask for "my house%.glb" as "my house" + an escape.
TEST(ViewerPages, NameTheChainBesideThemAsAUrl) {
    const auto folder = test::scratch_folder("viewer_pages");
    const std::vector<std::string> pages = write_viewer_pages((folder / "my house%.glb").string());
    ASSERT_EQ(pages.size(), 2u);
    EXPECT_EQ(pages[0], (folder / "my house%.three.html").string());
    EXPECT_EQ(pages[1], (folder / "my house%.babylon.html").string());
    for (const std::string& page : pages)
        EXPECT_NE(test::read_text(page).find("<meta name=\"boxlod-chain\" content=\"my%20house%25.glb\">"),
                  std::string::npos)
            << page;
}
