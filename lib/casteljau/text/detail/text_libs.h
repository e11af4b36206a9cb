// Internal to text/ (not installed): FreeType, HarfBuzz, fontconfig and
// FriBidi, opened on first use instead of linked.
//
// Why. Linked, the four and the six libraries they need are mapped and
// relocated at every process start, text or not: on the machines of issue
// 25, 86 of `casteljau --help`'s 274 page faults and 2.5 of its 10.5 ms,
// and as much of every icon's render. Opened by their sonames (read off the libraries at configure
// time, lib/CMakeLists.txt) the first time a font is matched, loaded or a
// paragraph laid out, they cost only the files that have text.
//
// How. Each function text/ calls is listed once below; TextLibs holds a
// pointer of the function's own type (decltype of the declaration in the
// library's header, so a signature cannot drift), and text/ calls through
// it: text_libs().hb_shape(...). The four are loaded together, once, from
// whichever thread asks first; if one fails nothing of text/ runs that
// needs them: FontDatabase matches no font, Font::load fails, bidi_levels
// gives the base level, and the SVG's "no font draws" warning says why.
#pragma once

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_ADVANCES_H
#include FT_MULTIPLE_MASTERS_H
#include FT_OUTLINE_H
#include FT_TRUETYPE_TABLES_H

#include <array>
#include <fontconfig/fontconfig.h>
#include <fribidi.h>
#include <hb-ot.h>
#include <hb.h>
#include <string>

namespace casteljau {

/// Every library function text/ calls, as X(library, function).
#define CASTELJAU_TEXT_FUNCTIONS(X)                                                                \
    X(FreeType, FT_Done_Face)                                                                      \
    X(FreeType, FT_Done_FreeType)                                                                  \
    X(FreeType, FT_Done_MM_Var)                                                                    \
    X(FreeType, FT_Get_Advance)                                                                    \
    X(FreeType, FT_Get_Char_Index)                                                                 \
    X(FreeType, FT_Get_MM_Var)                                                                     \
    X(FreeType, FT_Get_Sfnt_Table)                                                                 \
    X(FreeType, FT_Init_FreeType)                                                                  \
    X(FreeType, FT_Load_Glyph)                                                                     \
    X(FreeType, FT_Load_Sfnt_Table)                                                                \
    X(FreeType, FT_New_Face)                                                                       \
    X(FreeType, FT_New_Memory_Face)                                                                \
    X(FreeType, FT_Outline_Decompose)                                                              \
    X(FreeType, FT_Outline_EmboldenXY)                                                             \
    X(FreeType, FT_Set_Var_Design_Coordinates)                                                     \
    X(FreeType, FT_Sfnt_Table_Info)                                                                \
    X(HarfBuzz, hb_blob_create)                                                                    \
    X(HarfBuzz, hb_blob_create_from_file)                                                          \
    X(HarfBuzz, hb_blob_destroy)                                                                   \
    X(HarfBuzz, hb_buffer_add_utf32)                                                               \
    X(HarfBuzz, hb_buffer_create)                                                                  \
    X(HarfBuzz, hb_buffer_destroy)                                                                 \
    X(HarfBuzz, hb_buffer_get_glyph_infos)                                                         \
    X(HarfBuzz, hb_buffer_get_glyph_positions)                                                     \
    X(HarfBuzz, hb_buffer_guess_segment_properties)                                                \
    X(HarfBuzz, hb_buffer_set_direction)                                                           \
    X(HarfBuzz, hb_buffer_set_language)                                                            \
    X(HarfBuzz, hb_face_builder_add_table)                                                         \
    X(HarfBuzz, hb_face_builder_create)                                                            \
    X(HarfBuzz, hb_face_create)                                                                    \
    X(HarfBuzz, hb_face_destroy)                                                                   \
    X(HarfBuzz, hb_face_reference_blob)                                                            \
    X(HarfBuzz, hb_font_create)                                                                    \
    X(HarfBuzz, hb_font_destroy)                                                                   \
    X(HarfBuzz, hb_font_get_glyph_v_advance)                                                       \
    X(HarfBuzz, hb_font_get_glyph_v_origin)                                                        \
    X(HarfBuzz, hb_font_set_scale)                                                                 \
    X(HarfBuzz, hb_font_set_variations)                                                            \
    X(HarfBuzz, hb_language_from_string)                                                           \
    X(HarfBuzz, hb_ot_font_set_funcs)                                                              \
    X(HarfBuzz, hb_shape)                                                                          \
    X(HarfBuzz, hb_unicode_funcs_get_default)                                                      \
    X(HarfBuzz, hb_unicode_general_category)                                                       \
    X(Fontconfig, FcCharSetHasChar)                                                                \
    X(Fontconfig, FcConfigAppFontAddDir)                                                           \
    X(Fontconfig, FcConfigAppFontAddFile)                                                          \
    X(Fontconfig, FcConfigCreate)                                                                  \
    X(Fontconfig, FcConfigDestroy)                                                                 \
    X(Fontconfig, FcConfigParseAndLoadFromMemory)                                                  \
    X(Fontconfig, FcConfigSubstitute)                                                              \
    X(Fontconfig, FcDefaultSubstitute)                                                             \
    X(Fontconfig, FcFontMatch)                                                                     \
    X(Fontconfig, FcFontRenderPrepare)                                                             \
    X(Fontconfig, FcFontSetDestroy)                                                                \
    X(Fontconfig, FcFontSort)                                                                      \
    X(Fontconfig, FcInit)                                                                          \
    X(Fontconfig, FcInitLoadConfigAndFonts)                                                        \
    X(Fontconfig, FcPatternAddBool)                                                                \
    X(Fontconfig, FcPatternAddDouble)                                                              \
    X(Fontconfig, FcPatternAddInteger)                                                             \
    X(Fontconfig, FcPatternAddString)                                                              \
    X(Fontconfig, FcPatternCreate)                                                                 \
    X(Fontconfig, FcPatternDestroy)                                                                \
    X(Fontconfig, FcPatternGetBool)                                                                \
    X(Fontconfig, FcPatternGetCharSet)                                                             \
    X(Fontconfig, FcPatternGetInteger)                                                             \
    X(Fontconfig, FcPatternGetMatrix)                                                              \
    X(Fontconfig, FcPatternGetString)                                                              \
    X(Fontconfig, FcWeightFromOpenTypeDouble)                                                      \
    X(FriBidi, fribidi_get_bidi_types)                                                             \
    X(FriBidi, fribidi_get_bracket_types)                                                          \
    X(FriBidi, fribidi_get_par_embedding_levels_ex)

/// The four libraries' functions, or why they could not be loaded.
struct TextLibs {
    /// The libraries, in the order they are opened.
    enum Library { FreeType, HarfBuzz, Fontconfig, FriBidi, kLibraries };
    /// Their sonames, by Library.
    using Sonames = std::array<const char*, kLibraries>;

#define CASTELJAU_TEXT_POINTER(library, function) decltype(&::function) function = nullptr;
    CASTELJAU_TEXT_FUNCTIONS(CASTELJAU_TEXT_POINTER)
#undef CASTELJAU_TEXT_POINTER

    /// Empty once every function is there; else the loader's reason.
    std::string error;
    /// Whether every function is there.
    bool loaded() const noexcept { return error.empty(); }

    /// Opens the libraries named by `sonames` and looks every function up;
    /// on failure, `error` names the library or function and the loader's
    /// reason. They stay open for the process's life.
    static TextLibs load(const Sonames& sonames);
};

/// The build's libraries, loaded on the first call (thread-safe, once).
const TextLibs& text_libs();

} // namespace casteljau
