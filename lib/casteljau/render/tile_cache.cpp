#include "casteljau/render/tile_cache.h"

#include <algorithm>
#include <vector>

namespace casteljau {

const RasterImage* TileCache::find(const Pattern* pattern, const Affine& map) noexcept {
    for (Entry& e : entries_)
        if (e.of == pattern && e.of && e.map == map) {
            e.used = ++clock_;
            return &e.image;
        }
    return nullptr;
}

RasterImage& TileCache::insert(const Pattern* pattern, const Affine& map, int w, int h) {
    const auto by_use = [](const Entry& a, const Entry& b) { return a.used < b.used; };
    Entry& slot = *std::min_element(entries_.begin(), entries_.end(), by_use);
    const std::size_t n = std::size_t(w) * std::size_t(h);
    // Free the least recently used others' storage until this tile fits.
    while (allocated() - slot.image.pixels.capacity() + std::max(slot.image.pixels.capacity(), n) >
           max_pixels_) {
        Entry* oldest = nullptr;
        for (Entry& e : entries_)
            if (&e != &slot && e.image.pixels.capacity() > 0 && (!oldest || e.used < oldest->used))
                oldest = &e;
        if (!oldest) break; // only the slot holds storage: n alone is within the bound
        *oldest = Entry{};
    }
    // Exactly n when it grows (resize alone may double the capacity).
    if (slot.image.pixels.capacity() < n) {
        std::vector<Premul> grown;
        grown.reserve(n);
        slot.image.pixels.swap(grown);
    }
    slot.image.pixels.resize(n);
    slot.image.opaque8.clear(); // of the pixels before: found again once they are written
    slot.image.width = w;
    slot.image.height = h;
    slot.of = pattern;
    slot.map = map;
    slot.used = ++clock_;
    return slot.image;
}

void TileCache::clear() noexcept {
    for (Entry& e : entries_) e.of = nullptr, e.used = 0;
}

std::size_t TileCache::allocated() const noexcept {
    std::size_t sum = 0;
    for (const Entry& e : entries_) sum += e.image.pixels.capacity();
    return sum;
}

} // namespace casteljau
