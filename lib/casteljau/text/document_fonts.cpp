// Matching a document's own fonts (CSS Fonts 4, 5.2 "Matching font styles",
// steps 4a-4b, for the faces of one family):
//   style first: italic takes italic, then oblique, then normal; oblique
//   takes oblique, then italic, then normal; normal takes normal, then
//   oblique, then italic;
//   then weight, among faces of the chosen style: a face whose range holds
//   the desired weight w wins; else, for 400 <= w <= 500, the nearest heavier
//   face up to 500, then the nearest lighter one, then the nearest heavier;
//   for w < 400 the nearest lighter, then the nearest heavier; for w > 500
//   the nearest heavier, then the nearest lighter.
// Ties go to the face declared last, as later @font-face rules win.
// Stretch is not matched (no descriptor is read for it). Bold and italic
// a family lacks are synthesized (face_for), as for the system's fonts.
#include "casteljau/text/detail/document_fonts.h"

#include "casteljau/text/font.h"

#include <limits>
#include <tuple>

namespace casteljau {

namespace {

// Rank of a face's style for the wanted one: 0 is best.
int style_rank(FontStyle want, FontStyle have) {
    static constexpr int kOrder[3][3] = {
        // have: Normal, Italic, Oblique
        {0, 2, 1}, // want Normal: normal, oblique, italic
        {2, 0, 1}, // want Italic: italic, oblique, normal
        {2, 1, 0}, // want Oblique: oblique, italic, normal
    };
    return kOrder[int(want)][int(have)];
}

// Rank of a weight range for the wanted weight w: (tier, distance), lower is
// better.
std::pair<int, int> weight_rank(int w, int lo, int hi) {
    if (lo <= w && w <= hi) return {0, 0};
    const bool heavier = lo > w;
    const int distance = heavier ? lo - w : w - hi;
    if (w >= 400 && w <= 500) {
        if (heavier && lo <= 500) return {1, distance};
        return {heavier ? 3 : 2, distance};
    }
    const bool first = (w < 400) != heavier; // lighter first below 400, heavier above 500
    return {first ? 1 : 2, distance};
}

} // namespace

const FontDatabase::Layer::Entry* FontDatabase::Layer::best(const std::string& family,
                                                            const FontQuery& q,
                                                            std::optional<char32_t> c) const {
    const Entry* best = nullptr;
    std::tuple<int, int, int> best_rank{std::numeric_limits<int>::max(), 0, 0};
    for (const Entry& e : entries) {
        if (!same_family_name(e.descriptors.family, family)) continue;
        if (c && e.font->glyph_index(*c) == 0) continue;
        const auto [tier, distance] =
            weight_rank(q.weight, e.descriptors.weight_min, e.descriptors.weight_max);
        const std::tuple<int, int, int> rank{style_rank(q.style, e.descriptors.style), tier,
                                             distance};
        if (rank <= best_rank) best = &e, best_rank = rank;
    }
    return best;
}

FontFace FontDatabase::Layer::face_for(const Entry& e, const FontQuery& q) {
    FontFace face = e.face;
    // fontconfig's bold is 700 and medium 500 (its FC_WEIGHT_BOLD, _MEDIUM);
    // its slant is the matrix [1 0.2; 0 1].
    face.synthesis.bold = q.weight >= 700 && e.descriptors.weight_max <= 500;
    if (q.style != FontStyle::Normal && e.descriptors.style == FontStyle::Normal)
        face.synthesis.slant = 0.2;
    return face;
}

} // namespace casteljau
