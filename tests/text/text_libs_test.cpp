// The text libraries, opened on first use (text/detail/text_libs.h).
#include "casteljau/text/detail/text_libs.h"
#include "casteljau/text/font.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

TEST(TextLibs, TheBuildsLibrariesLoadWithEveryFunction) {
    const TextLibs& libs = text_libs();
    ASSERT_TRUE(libs.loaded()) << libs.error;
    EXPECT_EQ(text_libraries_error(), "");
#define CASTELJAU_EXPECT_FUNCTION(library, function) EXPECT_NE(libs.function, nullptr) << #function;
    CASTELJAU_TEXT_FUNCTIONS(CASTELJAU_EXPECT_FUNCTION)
#undef CASTELJAU_EXPECT_FUNCTION
    // Called through: HarfBuzz's own Unicode data.
    EXPECT_EQ(libs.hb_unicode_general_category(libs.hb_unicode_funcs_get_default(), U'\u0301'),
              HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK);
}

TEST(TextLibs, AMissingLibraryIsNamed) {
    TextLibs::Sonames names = {"libfreetype.so.6", "libcasteljau-no-such-library.so.9",
                               "libfontconfig.so.1", "libfribidi.so.0"};
    const TextLibs libs = TextLibs::load(names);
    EXPECT_FALSE(libs.loaded());
    EXPECT_NE(libs.error.find("libcasteljau-no-such-library.so.9"), std::string::npos)
        << libs.error;
}

TEST(TextLibs, ALibraryWithoutTheFunctionsIsNamedWithTheFirstMissing) {
    // FriBidi where FreeType should be: FT_Done_Face, the first FreeType
    // function of the list, is not there.
    TextLibs::Sonames names = {"libfribidi.so.0", "libharfbuzz.so.0", "libfontconfig.so.1",
                               "libfribidi.so.0"};
    const TextLibs libs = TextLibs::load(names);
    EXPECT_FALSE(libs.loaded());
    EXPECT_NE(libs.error.find("FT_Done_Face"), std::string::npos) << libs.error;
}

} // namespace
} // namespace casteljau
