// Loading a font with FreeType, and its glyph outlines as Paths.
//
// FreeType hands an outline as contours of on- and off-curve points;
// FT_Outline_Decompose turns them into move, line, conic (quadratic: what
// TrueType stores) and cubic (what CFF and CFF2 store) segments, which map
// one to one onto Path's segments: no approximation happens here, the
// flattener is the only place a curve is approximated. Glyphs are loaded
// with FT_LOAD_NO_SCALE (font units, so no hinting and no rounding) and, for
// variable fonts, at the design coordinates set by FT_Set_Var_Design_Coordinates.
#include "casteljau/text/font.h"

#include "casteljau/text/detail/font_impl.h"
#include "casteljau/text/detail/text_libs.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace casteljau {

Font::Impl::~Impl() {
    if (hb) text_libs().hb_font_destroy(hb);
    if (face) text_libs().FT_Done_Face(face);
    if (library) text_libs().FT_Done_FreeType(library);
}

Font::~Font() = default;

namespace {

FT_ULong tag_of(const char t[4]) {
    return FT_ULong(std::uint8_t(t[0])) << 24 | FT_ULong(std::uint8_t(t[1])) << 16 |
           FT_ULong(std::uint8_t(t[2])) << 8 | FT_ULong(std::uint8_t(t[3]));
}

// Sets the design axes named in `variations`, each clamped to its range;
// the others keep their defaults.
void set_variations(FT_Face face, const std::vector<FontVariation>& variations) {
    FT_MM_Var* mm = nullptr;
    if (variations.empty() || !FT_HAS_MULTIPLE_MASTERS(face) ||
        text_libs().FT_Get_MM_Var(face, &mm) != 0)
        return;
    std::vector<FT_Fixed> coords(mm->num_axis);
    for (FT_UInt i = 0; i < mm->num_axis; ++i) {
        const FT_Var_Axis& axis = mm->axis[i];
        coords[i] = axis.def;
        for (const FontVariation& v : variations)
            if (tag_of(v.tag) == axis.tag && std::isfinite(v.value))
                coords[i] = std::clamp(FT_Fixed(std::lround(v.value * 65536.0)), axis.minimum,
                                       axis.maximum);
    }
    text_libs().FT_Set_Var_Design_Coordinates(face, mm->num_axis, coords.data());
    text_libs().FT_Done_MM_Var(face->glyph->library, mm);
}

FontMetrics metrics_of(FT_Face face) {
    FontMetrics m;
    m.units_per_em = face->units_per_EM > 0 ? face->units_per_EM : 1000;
    m.ascender = face->ascender;
    m.descender = face->descender;
    m.underline_position = face->underline_position;
    m.underline_thickness = face->underline_thickness;
    // The x-height and cap height of the OS/2 table (version 2 on), else
    // the heights of the glyphs x and H, as browsers measure them, else
    // proportions of the em.
    m.x_height = m.units_per_em / 2;
    m.cap_height = m.units_per_em * 0.7;
    const auto* os2 = static_cast<const TT_OS2*>(text_libs().FT_Get_Sfnt_Table(face, FT_SFNT_OS2));
    if (os2 && os2->version == 0xFFFF) os2 = nullptr; // FreeType's mark of a missing table
    const auto top_of = [&](char32_t c, double& out) {
        const FT_UInt g = text_libs().FT_Get_Char_Index(face, c);
        if (g != 0 &&
            text_libs().FT_Load_Glyph(face, g, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0 &&
            face->glyph->metrics.horiBearingY > 0)
            out = double(face->glyph->metrics.horiBearingY);
    };
    if (os2 && os2->version >= 2 && os2->sxHeight > 0)
        m.x_height = os2->sxHeight;
    else
        top_of('x', m.x_height);
    if (os2 && os2->version >= 2 && os2->sCapHeight > 0)
        m.cap_height = os2->sCapHeight;
    else
        top_of('H', m.cap_height);
    if (m.underline_thickness <= 0) m.underline_thickness = m.units_per_em / 14;
    m.strikeout_thickness =
        os2 && os2->yStrikeoutSize > 0 ? os2->yStrikeoutSize : m.underline_thickness;
    m.strikeout_position = os2 && os2->yStrikeoutPosition > 0
                               ? os2->yStrikeoutPosition - m.strikeout_thickness / 2 // its top
                               : m.x_height / 2;
    if (m.ascender <= 0 && m.descender >= 0) // no usable vertical metrics: the em's usual split
        m.ascender = m.units_per_em * 0.8, m.descender = -m.units_per_em * 0.2;
    return m;
}

// Coordinates come doubled (the outline functions' shift of 1): the
// on-curve point TrueType implies between two off-curve points is their
// midpoint, which FreeType computes in integers; doubled, it is exact.
Point pt(const FT_Vector* v) { return {v->x / 2.0, v->y / 2.0}; }

struct Decomposer {
    static int move(const FT_Vector* to, void* user) {
        static_cast<Path*>(user)->move_to(pt(to));
        return 0;
    }
    static int line(const FT_Vector* to, void* user) {
        static_cast<Path*>(user)->line_to(pt(to));
        return 0;
    }
    static int conic(const FT_Vector* c, const FT_Vector* to, void* user) {
        static_cast<Path*>(user)->quad_to(pt(c), pt(to));
        return 0;
    }
    static int cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
        static_cast<Path*>(user)->cubic_to(pt(c1), pt(c2), pt(to));
        return 0;
    }
};

// The contours of an outline, each closed: a glyph is a filled area.
Path path_of(FT_Outline& outline) {
    static const FT_Outline_Funcs funcs = {
        Decomposer::move, Decomposer::line, Decomposer::conic, Decomposer::cubic, 1, 0};
    Path contours;
    if (text_libs().FT_Outline_Decompose(&outline, &funcs, &contours) != 0) return {};
    Path closed;
    for (Subpath sp : contours.subpaths()) {
        sp.closed = true;
        closed.add_subpath(sp);
    }
    return closed;
}

// Starts FreeType and opens the face with `open`; the reason it failed, or null.
template <class Open>
const char* open_face(Font::Impl& impl, Open open) {
    if (!text_libs().loaded()) return text_libs().error.c_str();
    if (text_libs().FT_Init_FreeType(&impl.library) != 0) return "FreeType does not start";
    if (open() != 0) return "not a font FreeType reads";
    if (!FT_IS_SCALABLE(impl.face)) return "a bitmap font, without outlines";
    return nullptr;
}

} // namespace

std::shared_ptr<Font> Font::load(const std::string& file, int index,
                                 const std::vector<FontVariation>& variations, std::string* error) {
    std::shared_ptr<Font> font(new Font);
    font->impl_ = std::make_unique<Impl>();
    Impl& impl = *font->impl_;
    if (const char* what = open_face(impl, [&] {
            return text_libs().FT_New_Face(impl.library, file.c_str(), index, &impl.face);
        })) {
        if (error) *error = file + ": " + what;
        return nullptr;
    }
    hb_blob_t* blob = text_libs().hb_blob_create_from_file(file.c_str());
    hb_face_t* tables = text_libs().hb_face_create(blob, unsigned(index));
    text_libs().hb_blob_destroy(blob);
    return finish(std::move(font), variations, tables);
}

std::shared_ptr<Font> Font::load(std::shared_ptr<const std::vector<unsigned char>> data,
                                 const std::string& name, int index,
                                 const std::vector<FontVariation>& variations, std::string* error) {
    std::shared_ptr<Font> font(new Font);
    font->impl_ = std::make_unique<Impl>();
    Impl& impl = *font->impl_;
    impl.data = std::move(data);
    if (const char* what = open_face(impl, [&] {
            return text_libs().FT_New_Memory_Face(impl.library, impl.data->data(),
                                                  FT_Long(impl.data->size()), index, &impl.face);
        })) {
        if (error) *error = name + ": " + what;
        return nullptr;
    }
    // HarfBuzz reads sfnt tables, and a WOFF or WOFF2 font is compressed:
    // the tables are taken from FreeType, which decompressed them, each
    // copied once now (HarfBuzz would otherwise ask FreeType for them
    // lazily, from the shaping thread, while another reads outlines).
    hb_face_t* tables = text_libs().hb_face_builder_create();
    FT_ULong tag = 0, length = 0;
    for (FT_UInt i = 0; text_libs().FT_Sfnt_Table_Info(impl.face, i, &tag, &length) == 0; ++i) {
        std::vector<FT_Byte> bytes(length);
        if (length == 0 ||
            text_libs().FT_Load_Sfnt_Table(impl.face, tag, 0, bytes.data(), &length) != 0)
            continue;
        hb_blob_t* blob = text_libs().hb_blob_create(reinterpret_cast<const char*>(bytes.data()),
                                                     unsigned(length), HB_MEMORY_MODE_DUPLICATE,
                                                     nullptr, nullptr);
        text_libs().hb_face_builder_add_table(tables, hb_tag_t(tag), blob);
        text_libs().hb_blob_destroy(blob);
    }
    hb_blob_t* built = text_libs().hb_face_reference_blob(tables);
    text_libs().hb_face_destroy(tables);
    tables = text_libs().hb_face_create(built, 0);
    text_libs().hb_blob_destroy(built);
    return finish(std::move(font), variations, tables);
}

std::shared_ptr<Font> Font::finish(std::shared_ptr<Font> font,
                                   const std::vector<FontVariation>& variations,
                                   hb_face_t* tables) {
    Impl& impl = *font->impl_;
    set_variations(impl.face, variations);
    impl.hb = text_libs().hb_font_create(tables);
    text_libs().hb_face_destroy(tables);
    text_libs().hb_ot_font_set_funcs(impl.hb);
    // Shaping in font units: HarfBuzz's positions are then exact, unhinted.
    text_libs().hb_font_set_scale(impl.hb, int(impl.face->units_per_EM),
                                  int(impl.face->units_per_EM));
    std::vector<hb_variation_t> hb_variations;
    for (const FontVariation& v : variations)
        if (std::isfinite(v.value))
            hb_variations.push_back({hb_tag_t(tag_of(v.tag)), float(v.value)});
    text_libs().hb_font_set_variations(impl.hb, hb_variations.data(),
                                       unsigned(hb_variations.size()));
    font->metrics_ = metrics_of(impl.face);
    font->family_ = impl.face->family_name ? impl.face->family_name : "";
    font->glyph_count_ = std::size_t(std::max<FT_Long>(impl.face->num_glyphs, 0));
    FT_MM_Var* mm = nullptr;
    if (FT_HAS_MULTIPLE_MASTERS(impl.face) && text_libs().FT_Get_MM_Var(impl.face, &mm) == 0) {
        for (FT_UInt i = 0; i < mm->num_axis; ++i) font->axes_.push_back(mm->axis[i].tag);
        text_libs().FT_Done_MM_Var(impl.library, mm);
    }
    return font;
}

bool Font::has_axis(const char tag[4]) const {
    return std::find(axes_.begin(), axes_.end(), tag_of(tag)) != axes_.end();
}

std::uint32_t Font::glyph_index(char32_t c) const {
    std::lock_guard lock(mutex_);
    return text_libs().FT_Get_Char_Index(impl_->face, FT_ULong(c));
}

// The outline's point count is bounded by its type (Font::kMaxOutlinePoints).
static_assert(std::numeric_limits<decltype(FT_Outline::n_points)>::max() <=
              Font::kMaxOutlinePoints);

const Path& Font::outline(std::uint32_t glyph) const {
    std::lock_guard lock(mutex_);
    if (const auto it = outlines_.find(glyph); it != outlines_.end()) return it->second;
    Path& path = outlines_[glyph];
    FT_Face face = impl_->face;
    if (glyph < glyph_count_ &&
        text_libs().FT_Load_Glyph(face, glyph,
                                  FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) == 0 &&
        face->glyph->format == FT_GLYPH_FORMAT_OUTLINE) {
        FT_Outline& outline = face->glyph->outline;
        // FT_GlyphSlot_Embolden's strength, 1/24 em (font units here: no
        // scale), grown right and up as it grows them.
        if (synthesis_.bold) {
            const FT_Pos strength = FT_Pos(face->units_per_EM) / 24;
            text_libs().FT_Outline_EmboldenXY(&outline, strength, strength);
        }
        path = path_of(outline);
        if (synthesis_.slant != 0) path.transform(Affine{1, 0, synthesis_.slant, 1, 0, 0});
    }
    return path;
}

double Font::advance(std::uint32_t glyph) const {
    std::lock_guard lock(mutex_);
    FT_Fixed a = 0;
    if (text_libs().FT_Get_Advance(impl_->face, glyph, FT_LOAD_NO_SCALE, &a) != 0) return 0;
    return double(a);
}

double Font::vertical_advance(std::uint32_t glyph) const {
    return -double(
        text_libs().hb_font_get_glyph_v_advance(impl_->hb, glyph)); // HarfBuzz's is y up: negative
}

Vec2 Font::vertical_origin(std::uint32_t glyph) const {
    hb_position_t x = 0, y = 0;
    text_libs().hb_font_get_glyph_v_origin(impl_->hb, glyph, &x, &y);
    return {double(x), double(y)};
}

} // namespace casteljau
