// A tiny application built against the installed package.
#include <casteljau/curve/path_data.h>
#include <casteljau/flatten/path_flatten.h>
#include <cstdio>

int main() {
    const auto parsed = casteljau::parse_path_data("M0 0 C 50 100 150 -100 200 0");
    if (parsed.error) return 1;
    std::vector<casteljau::Polyline> out;
    const auto stats = casteljau::flatten_path(parsed.path, casteljau::Affine::identity(), {}, out);
    std::printf("segments %zu\n", stats.segments_out);
    return stats.segments_out > 0 ? 0 : 1;
}
