// A FontDatabase layer's own faces: a document's @font-face fonts, and
// which of them a query takes (text/document_fonts.cpp).
#pragma once

#include "casteljau/text/font_database.h"

#include <optional>
#include <string>
#include <vector>

namespace casteljau {

struct FontDatabase::Layer {
    struct Entry {
        FontFaceDescriptors descriptors;
        FontFace face;
        std::shared_ptr<const Font> font; // loaded when added: the check that it is a font
    };
    std::vector<Entry> entries;

    /// The face of `family` the query takes, among those that have `c` when
    /// given; null when the layer has none of that family.
    const Entry* best(const std::string& family, const FontQuery& q,
                      std::optional<char32_t> c) const;
};

} // namespace casteljau
