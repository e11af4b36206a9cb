// Shaping a run with HarfBuzz (see shaping.h). The whole text goes into the
// buffer as context and only [begin, end) is shaped, so that joining and
// contextual forms see their neighbours (hb_buffer_add_utf32's item range).
// The font's scale is its units per em, so positions come out in font units.
#include "casteljau/text/shaping.h"

#include "casteljau/text/detail/font_impl.h"
#include "casteljau/text/detail/text_libs.h"

namespace casteljau {

std::vector<ShapedGlyph> shape_run(const Font& font, std::u32string_view text, std::size_t begin,
                                   std::size_t end, const ShapeOptions& options) {
    hb_buffer_t* buf = text_libs().hb_buffer_create();
    text_libs().hb_buffer_add_utf32(buf, reinterpret_cast<const std::uint32_t*>(text.data()),
                                    int(text.size()), unsigned(begin), int(end - begin));
    text_libs().hb_buffer_set_direction(
        buf, options.direction == TextDirection::Rtl   ? HB_DIRECTION_RTL
             : options.direction == TextDirection::Ttb ? HB_DIRECTION_TTB
                                                       : HB_DIRECTION_LTR);
    if (!options.language.empty())
        text_libs().hb_buffer_set_language(
            buf, text_libs().hb_language_from_string(options.language.c_str(),
                                                     int(options.language.size())));
    text_libs().hb_buffer_guess_segment_properties(buf); // the script, from the text
    std::vector<hb_feature_t> features;
    for (const FontFeature& f : options.features)
        features.push_back({HB_TAG(f.tag[0], f.tag[1], f.tag[2], f.tag[3]), f.on ? 1u : 0u,
                            HB_FEATURE_GLOBAL_START, HB_FEATURE_GLOBAL_END});
    text_libs().hb_shape(font.impl().hb, buf, features.data(), unsigned(features.size()));
    unsigned n = 0;
    const hb_glyph_info_t* info = text_libs().hb_buffer_get_glyph_infos(buf, &n);
    const hb_glyph_position_t* pos = text_libs().hb_buffer_get_glyph_positions(buf, &n);
    std::vector<ShapedGlyph> glyphs(n);
    for (unsigned i = 0; i < n; ++i)
        glyphs[i] = {info[i].codepoint,        info[i].cluster,         double(pos[i].x_advance),
                     double(pos[i].y_advance), double(pos[i].x_offset), double(pos[i].y_offset)};
    text_libs().hb_buffer_destroy(buf);
    return glyphs;
}

} // namespace casteljau
