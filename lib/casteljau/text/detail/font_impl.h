// Internal to text/ (not installed): what a Font holds of FreeType and
// HarfBuzz. HarfBuzz reads the font's tables itself (its own OpenType
// functions), so shaping needs no lock: HarfBuzz fonts are thread-safe once
// made, FreeType faces are not.
#pragma once

#include "casteljau/text/font.h"

#include <ft2build.h>
#include <memory>
#include <vector>
#include FT_FREETYPE_H
#include <hb.h>

namespace casteljau {

struct Font::Impl {
    FT_Library library = nullptr; // one per font: FreeType libraries are not thread-safe
    FT_Face face = nullptr;
    hb_font_t* hb = nullptr;
    /// A face loaded from memory: its bytes, which FreeType reads for the
    /// face's life.
    std::shared_ptr<const std::vector<unsigned char>> data;
    ~Impl();
};

} // namespace casteljau
