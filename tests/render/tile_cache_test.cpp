// The pattern tile cache: a tile is found under its pattern and map only,
// the least recently used is replaced first, and the storage of all entries
// stays within the bound whatever the sequence of tiles (seeded property).
#include "casteljau/render/tile_cache.h"
#include "casteljau/scene/scene.h"
#include "corpus.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <vector>

namespace casteljau {
namespace {

TEST(TileCache, FindsATileUnderItsPatternAndMapOnly) {
    TileCache cache(1000);
    const Pattern a, b;
    const Affine m = Affine::scale(2);
    RasterImage& tile = cache.insert(&a, m, 4, 3);
    EXPECT_EQ(tile.width, 4);
    EXPECT_EQ(tile.height, 3);
    EXPECT_EQ(tile.pixels.size(), 12u);
    EXPECT_EQ(cache.find(&a, m), &tile);
    EXPECT_EQ(cache.find(&b, m), nullptr);
    EXPECT_EQ(cache.find(&a, Affine::scale(2.0000001)), nullptr);
    EXPECT_EQ(cache.find(nullptr, Affine::identity()), nullptr); // empty entries match nothing
    cache.clear();
    EXPECT_EQ(cache.find(&a, m), nullptr);
    EXPECT_GE(cache.allocated(), 12u); // cleared, its storage kept for the next frame
}

// A slot taken for a new tile forgets the 8-bit copy of the tile before: the
// new pixels are not yet written, and a stale copy would be drawn in their
// place (raster_image.h).
TEST(TileCache, ANewTileHasNo8BitCopyOfTheOldOne) {
    TileCache cache(1000);
    std::vector<Pattern> patterns(TileCache::kEntries + 1);
    for (Pattern& p : patterns) {
        RasterImage& tile = cache.insert(&p, Affine::identity(), 2, 2);
        EXPECT_TRUE(tile.opaque8.empty());
        std::fill(tile.pixels.begin(), tile.pixels.end(), Premul{0.5f, 0.5f, 0.5f, 1});
        tile.find_opaque8();
        EXPECT_EQ(tile.opaque8.size(), 4u);
    }
}

TEST(TileCache, TheLeastRecentlyUsedTileIsReplacedFirst) {
    TileCache cache(1000);
    std::vector<Pattern> patterns(TileCache::kEntries + 1);
    for (int i = 0; i < TileCache::kEntries; ++i)
        cache.insert(&patterns[std::size_t(i)], Affine::identity(), 2, 2);
    ASSERT_NE(cache.find(&patterns[0], Affine::identity()), nullptr); // 0 used last now
    cache.insert(&patterns.back(), Affine::identity(), 2, 2);
    EXPECT_NE(cache.find(&patterns[0], Affine::identity()), nullptr);
    EXPECT_EQ(cache.find(&patterns[1], Affine::identity()), nullptr) << "the oldest goes";
    for (int i = 2; i < TileCache::kEntries; ++i)
        EXPECT_NE(cache.find(&patterns[std::size_t(i)], Affine::identity()), nullptr) << i;
}

TEST(TileCache, StorageStaysWithinTheBoundForAnySequence) {
    constexpr std::size_t kBound = 4096;
    testing::Rng rng(31);
    std::vector<Pattern> patterns(7);
    TileCache cache(kBound);
    for (int step = 0; step < 2000; ++step) {
        const Pattern* p = &patterns[std::size_t(rng.integer(0, 6))];
        const Affine m = Affine::scale(rng.integer(1, 3));
        if (step % 97 == 0) cache.clear();
        if (cache.find(p, m)) continue;
        // Mostly small tiles, now and then one of up to the whole bound.
        const int w = rng.integer(1, 64);
        const int h = std::max(1, step % 13 == 0 ? int(kBound) / w : rng.integer(1, 16));
        RasterImage& tile = cache.insert(p, m, w, h);
        ASSERT_EQ(tile.pixels.size(), std::size_t(w) * std::size_t(h));
        ASSERT_LE(cache.allocated(), kBound) << "step " << step << ", tile " << w << " x " << h;
        ASSERT_EQ(cache.find(p, m), &tile) << "step " << step;
    }
}

} // namespace
} // namespace casteljau
