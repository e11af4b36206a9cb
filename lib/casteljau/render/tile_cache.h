// TileCache: the pattern tiles a renderer keeps while it draws a frame, so
// that shapes painted with alternating patterns, or the same pattern under
// alternating maps, do not redraw their tiles shape after shape.
//
// A tile is kept under its pattern and its map (tile space -> device), the
// two things its pixels depend on; a few entries (kEntries), the least
// recently used replaced first. Storage is bounded in all, not per entry:
// the pixels allocated for every entry together stay within the bound given
// (the renderer gives kMaxTilePixels, what its single tile held before), so
// a large tile frees the storage of the least recently used entries first.
#pragma once

#include "casteljau/geom/affine.h"
#include "casteljau/paint/raster_image.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace casteljau {

struct Pattern;

/// Pattern tiles by (pattern, map), least recently used replaced first.
class TileCache {
  public:
    /// Tiles kept at once.
    static constexpr int kEntries = 4;

    /// A cache whose entries allocate at most `max_pixels` pixels in all.
    explicit TileCache(std::size_t max_pixels) noexcept : max_pixels_(max_pixels) {}
    /// The tile of `pattern` under `map`, or null when none is kept.
    const RasterImage* find(const Pattern* pattern, const Affine& map) noexcept;
    /// A tile of w x h pixels (w h <= the bound) for `pattern` under `map`,
    /// kept in place of the least recently used; the caller writes its pixels
    /// (and then finds their opaque8: its bytes, a quarter of the pixels',
    /// are not counted against the bound).
    RasterImage& insert(const Pattern* pattern, const Affine& map, int w, int h);
    /// Forgets every tile (a new scene may hold other patterns at the same
    /// addresses), keeping the storage.
    void clear() noexcept;
    /// Pixels allocated by all entries together.
    std::size_t allocated() const noexcept;

  private:
    struct Entry {
        const Pattern* of = nullptr;
        Affine map;
        RasterImage image;
        std::uint64_t used = 0; ///< the clock at the last find or insert
    };
    std::array<Entry, kEntries> entries_;
    std::uint64_t clock_ = 0;
    std::size_t max_pixels_;
};

} // namespace casteljau
