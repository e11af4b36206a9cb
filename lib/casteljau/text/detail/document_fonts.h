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
    /// The entry's face for the query, with the bold or italic it lacks
    /// synthesized by the rule fontconfig's 90-synthetic.conf gives the
    /// system's fonts: bold for a weight of 700 or more from a face of 500
    /// or less, a slant of 0.2 for italic or oblique from a normal face.
    static FontFace face_for(const Entry& e, const FontQuery& q);
};

} // namespace casteljau
