// Text against the same outlines as paths (the acceptance: a page of
// about 5,000 glyphs renders within 2x of its outlines given as paths, so
// that layout and shaping are not the bottleneck). The page: 112 lines of
// generated English text (seeded, so every run draws the same page) in two
// columns, Noto Sans 12 px on a US Letter page (816 x 1056 px), each line a
// <text> with a bold tspan and a coloured one.
// - BM_TextPage_Svg: parse_svg + render of the page as <text>, with a font
//   database made once (the steady state of an application or a server);
// - BM_TextPage_Paths: parse_svg + render of the same page with each text
//   span's outline written as a <path> (taken from the scene the text page
//   reads to), so both sides pay for an SVG parse and the same render;
// - BM_TextPage_Ratio: both in every iteration, in CPU time of the thread,
//   so their ratio is measured under the same machine load (on a shared
//   machine one side alone drifts by 20%), split into parse and render;
// - BM_TextPage_FirstParse: the text page with a new database every time:
//   the cold cost (fontconfig's scan of the font folders, fonts loaded,
//   outlines read) that a one-shot command-line run pays;
// - BM_Shape_5000_Glyphs: shape_paragraph alone on the page's lines;
// - BM_TextToPath_Line: text_to_path on one line.
// Every render is one thread onto the float canvas, as in render_bench.
#include "casteljau/render/bands.h"
#include "casteljau/svg/reader.h"
#include "casteljau/text/layout.h"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace casteljau {
namespace {

constexpr int kLines = 112;     // in two columns of 56
constexpr int kInkPerLine = 44; // non-space characters a line holds at least
constexpr double kPageW = 816, kPageH = 1056;
const char* const kFontDirs[] = {"/usr/share/fonts/truetype/noto",
                                 "/usr/share/fonts/truetype/dejavu"};

std::unique_ptr<FontDatabase> make_fonts() {
    auto db = FontDatabase::empty();
    for (const char* dir : kFontDirs)
        if (!db->add_font_dir(dir)) {
            std::fprintf(stderr, "text_bench: no font folder %s\n", dir);
            std::exit(1);
        }
    return db;
}

// Made once: fontconfig scans the folders (hundreds of files) and each
// font, once loaded, keeps the outlines it has read.
FontDatabase& warm_fonts() {
    static const std::unique_ptr<FontDatabase> db = make_fonts();
    return *db;
}

// One line of the page in five runs: regular, bold, regular, red, regular.
// Words drawn from a list whose first third are the commonest English
// words, so that the letters, and the glyphs the fonts cache, are those of
// ordinary prose, with some capitals, digits and punctuation.
struct PageLine {
    std::string runs[5];
    std::string all() const { return runs[0] + runs[1] + runs[2] + runs[3] + runs[4]; }
};

std::vector<PageLine> page_lines() {
    static const char* const words[] = {
        "the",      "of",      "and",      "to",        "a",        "in",         "is",
        "that",     "for",     "it",       "as",        "was",      "with",       "be",
        "by",       "on",      "not",      "he",        "this",     "are",        "or",
        "his",      "from",    "at",       "which",     "but",      "have",       "an",
        "they",     "you",     "were",     "their",     "one",      "all",        "we",
        "curve",    "glyph",   "outline",  "quadratic", "renderer", "pixel",      "coverage",
        "Bezier",   "control", "point",    "segment",   "winding",  "shaping",    "kerning",
        "baseline", "advance", "ligature", "paragraph", "language", "between",    "through",
        "during",   "without", "because",  "however",   "number",   "people",     "water",
        "Monday",   "London",  "quickly",  "brown",     "fox",      "jumps",      "over",
        "lazy",     "dog",     "sphinx",   "of",        "black",    "quartz",     "judge",
        "my",       "vow",     "(1998)",   "42%",       "e.g.",     "well-known", "it's",
    };
    constexpr std::size_t n = sizeof words / sizeof words[0];
    std::uint64_t s = 12345;
    const auto next = [&] {
        s = s * 6364136223846793005u + 1442695040888963407u;
        return std::size_t(s >> 33);
    };
    std::vector<PageLine> lines(kLines);
    for (int i = 0; i < kLines; ++i) {
        // Words until the line holds kInkPerLine inked characters; the bold
        // run is the 3rd and 4th words, the red one a word further on (the
        // 6th to 8th, by line), each run holding its leading space.
        int ink = 0, word = 0;
        const int red = 6 + i % 3;
        while (ink < kInkPerLine) {
            const std::string w = words[next() % n];
            const int run = word < 2 ? 0 : word < 4 ? 1 : word < red ? 2 : word == red ? 3 : 4;
            std::string& r = lines[std::size_t(i)].runs[run];
            if (word > 0) r += ' ';
            r += w;
            ink += int(w.size()), ++word;
        }
    }
    return lines;
}

std::string xml_escaped(const std::string& s) {
    std::string out;
    for (char c : s) c == '&' ? out += "&amp;" : c == '<' ? out += "&lt;" : out += c;
    return out;
}

// The page as SVG text: two columns of 56 lines, 17 px apart.
std::string text_page_svg() {
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"816\" height=\"1056\">\n"
                      "<rect width=\"816\" height=\"1056\" fill=\"white\"/>\n"
                      "<g font-family=\"Noto Sans\" font-size=\"12\" fill=\"#1a1a1a\">\n";
    const std::vector<PageLine> lines = page_lines();
    for (int i = 0; i < kLines; ++i) {
        const PageLine& l = lines[std::size_t(i)];
        char pos[64];
        std::snprintf(pos, sizeof pos, "<text x=\"%d\" y=\"%d\">", i < kLines / 2 ? 40 : 424,
                      56 + 17 * (i % (kLines / 2)));
        svg += pos + xml_escaped(l.runs[0]) + "<tspan font-weight=\"bold\">" +
               xml_escaped(l.runs[1]) + "</tspan>" + xml_escaped(l.runs[2]) +
               "<tspan fill=\"#b02a1e\">" + xml_escaped(l.runs[3]) + "</tspan>" +
               xml_escaped(l.runs[4]) + "</text>\n";
    }
    return svg + "</g>\n</svg>\n";
}

Scene read(std::string_view svg, const char* name, FontDatabase& fonts) {
    SvgOptions o;
    o.fonts = &fonts;
    SvgResult r = parse_svg(svg, name, o);
    if (!r.scene) {
        std::fprintf(stderr, "text_bench: %s\n", r.error.c_str());
        std::exit(1);
    }
    if (!r.warnings.empty()) std::fprintf(stderr, "text_bench: %s\n", r.warnings[0].text().c_str());
    return std::move(*r.scene);
}

// Path data with 7 significant digits: within 0.0005 px on this page, far
// below the 0.25 px flattening tolerance, so both pages draw the same.
void put(std::string& out, char cmd, std::initializer_list<Point> pts) {
    char buf[48];
    out += cmd;
    for (Point p : pts) {
        std::snprintf(buf, sizeof buf, "%.7g %.7g ", p.x, p.y);
        out += buf;
    }
}

std::string path_data(const Path& path) {
    std::string d;
    for (const Subpath& sp : path.subpaths()) {
        put(d, 'M', {sp.start});
        for (const Segment& s : sp.segments) {
            if (const auto* l = std::get_if<Line>(&s))
                put(d, 'L', {l->p[1]});
            else if (const auto* q = std::get_if<QuadBez>(&s))
                put(d, 'Q', {q->p[1], q->p[2]});
            else if (const auto* c = std::get_if<CubicBez>(&s))
                put(d, 'C', {c->p[1], c->p[2], c->p[3]});
            else { // glyphs have no conics; a straight stand-in keeps the count
                put(d, 'L', {segment_end(s)});
                std::fprintf(stderr, "text_bench: a conic in a glyph outline\n");
            }
        }
        if (sp.closed) d += 'Z';
    }
    return d;
}

int channel(float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255)); }

void write_shapes(const Group& g, std::string& out, std::size_t& glyph_shapes) {
    for (const Node& n : g.children) {
        if (const auto* sub = std::get_if<Group>(&n.item)) {
            write_shapes(*sub, out, glyph_shapes);
            continue;
        }
        const Shape& s = std::get<Shape>(n.item);
        const Affine& m = s.transform;
        char head[256];
        const Rgba c = s.fill ? s.fill->color : Rgba{};
        std::snprintf(
            head, sizeof head,
            "<path transform=\"matrix(%.9g %.9g %.9g %.9g %.9g %.9g)\" fill=\"#%02x%02x%02x\" d=\"",
            m.a, m.b, m.c, m.d, m.e, m.f, channel(c.r), channel(c.g), channel(c.b));
        out += head + path_data(s.path) + "\"/>\n";
        ++glyph_shapes;
    }
}

// The same page with every shape of the text page's scene written as a
// <path>: the outlines the text reads to, in the same user space under the
// same transforms, with the same fills.
std::string paths_page_svg(const Scene& text_scene) {
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"816\" height=\"1056\">\n";
    std::size_t shapes = 0;
    write_shapes(text_scene.root, svg, shapes);
    return svg + "</svg>\n";
}

// The segments of a scene's shapes.
double segments_of(const Group& g) {
    double n = 0;
    for (const Node& c : g.children)
        if (const auto* sub = std::get_if<Group>(&c.item))
            n += segments_of(*sub);
        else
            n += double(std::get<Shape>(c.item).path.segment_count());
    return n;
}

struct Page {
    std::string text_svg, paths_svg;
    Scene text_scene;
    double glyphs = 0; // characters drawn with an outline (spaces have none)
    double segments = 0;
};

const Page& page() {
    static const Page p = [] {
        Page p;
        p.text_svg = text_page_svg();
        p.text_scene = read(p.text_svg, "text_page.svg", warm_fonts());
        p.paths_svg = paths_page_svg(p.text_scene);
        for (const PageLine& l : page_lines())
            for (char c : l.all()) p.glyphs += c != ' ';
        p.segments = segments_of(p.text_scene.root);
        return p;
    }();
    return p;
}

struct Frame {
    BandRenderer renderer;
    Canvas canvas{int(kPageW), int(kPageH)};
    void draw(const Scene& s) {
        renderer.render(s, Affine::identity(), canvas, RenderOptions{}, Premul{}, 1);
        benchmark::DoNotOptimize(canvas.row(0));
    }
};

void page_counters(benchmark::State& state, const std::string& svg) {
    state.counters["glyphs"] = page().glyphs;
    state.counters["segments"] = page().segments;
    state.counters["svg_KiB"] = double(svg.size()) / 1024;
}

void BM_TextPage_Svg(benchmark::State& state) {
    const Page& p = page();
    Frame f;
    for (auto _ : state) {
        const Scene s = read(p.text_svg, "text_page.svg", warm_fonts());
        f.draw(s);
    }
    page_counters(state, p.text_svg);
}
BENCHMARK(BM_TextPage_Svg)->Unit(benchmark::kMillisecond);

void BM_TextPage_Paths(benchmark::State& state) {
    const Page& p = page();
    Frame f;
    for (auto _ : state) {
        const Scene s = read(p.paths_svg, "paths_page.svg", warm_fonts());
        f.draw(s);
    }
    page_counters(state, p.paths_svg);
    // Both pages draw the same: the mean difference of their pictures, in
    // 1/255 per channel (0 up to the rounding of the path data).
    Frame t;
    t.draw(p.text_scene);
    double diff = 0;
    for (int y = 0; y < t.canvas.height(); ++y) {
        const Premul* a = std::as_const(t.canvas).row(y);
        const Premul* b = std::as_const(f.canvas).row(y);
        for (int x = 0; x < t.canvas.width(); ++x)
            diff += std::abs(a[x].r - b[x].r) + std::abs(a[x].g - b[x].g) +
                    std::abs(a[x].b - b[x].b) + std::abs(a[x].a - b[x].a);
    }
    state.counters["diff_255"] = diff * 255 / (4.0 * kPageW * kPageH);
}
BENCHMARK(BM_TextPage_Paths)->Unit(benchmark::kMillisecond);

// The calling thread's CPU time, ms: everything here runs on that thread
// (a one-thread BandRenderer starts none), and on a shared machine the wall
// clock also counts the time other processes hold the core.
double thread_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Both pages in every iteration, parse and render timed apart, so that the
// ratio is taken under one machine load. Counters in ms of CPU per page;
// `ratio` is the text page's total over the paths page's (the acceptance:
// at most 2).
void BM_TextPage_Ratio(benchmark::State& state) {
    const Page& p = page();
    Frame f;
    double t[2][2] = {}; // [text, paths][parse, render]
    for (auto _ : state) {
        double spent = 0;
        for (int side = 0; side < 2; ++side) {
            const double a = thread_cpu_ms();
            const Scene s = read(side == 0 ? p.text_svg : p.paths_svg, "page.svg", warm_fonts());
            const double b = thread_cpu_ms();
            f.draw(s);
            const double c = thread_cpu_ms();
            t[side][0] += b - a, t[side][1] += c - b, spent += c - a;
        }
        state.SetIterationTime(spent * 1e-3);
    }
    const double n = double(state.iterations());
    state.counters["svg_parse_ms"] = t[0][0] / n;
    state.counters["svg_render_ms"] = t[0][1] / n;
    state.counters["paths_parse_ms"] = t[1][0] / n;
    state.counters["paths_render_ms"] = t[1][1] / n;
    state.counters["ratio"] = (t[0][0] + t[0][1]) / (t[1][0] + t[1][1]);
    state.counters["glyphs"] = p.glyphs;
}
BENCHMARK(BM_TextPage_Ratio)->UseManualTime()->Unit(benchmark::kMillisecond);

// The cold page: fontconfig scans the folders, the fonts are opened and
// every outline is read anew, as in a one-shot command-line run. Where
// fontconfig has no writable cache folder (it says so on stderr) it reads
// every font file's header each time; with its cache, less.
void BM_TextPage_FirstParse(benchmark::State& state) {
    const Page& p = page();
    Frame f;
    for (auto _ : state) {
        const std::unique_ptr<FontDatabase> fonts = make_fonts();
        const Scene s = read(p.text_svg, "text_page.svg", *fonts);
        f.draw(s);
    }
    page_counters(state, p.text_svg);
}
BENCHMARK(BM_TextPage_FirstParse)->Unit(benchmark::kMillisecond);

// The page's styles as the reader makes them: Noto Sans 12 px, regular and bold.
std::vector<TextStyle> page_styles() {
    TextStyle regular;
    regular.font.families = {"Noto Sans"};
    regular.size = 12;
    TextStyle bold = regular;
    bold.font.weight = 700;
    return {regular, bold};
}

// Layout alone: each of the page's 112 lines shaped as one paragraph, as
// the reader shapes each <text> (bidi, itemisation, font matching and
// fallback, HarfBuzz), without reading an outline.
void BM_Shape_5000_Glyphs(benchmark::State& state) {
    const std::vector<TextStyle> styles = page_styles();
    std::vector<std::u32string> texts;
    std::vector<std::vector<std::uint32_t>> style_ofs;
    for (const PageLine& l : page_lines()) {
        std::u32string t;
        std::vector<std::uint32_t> style_of;
        for (int run = 0; run < 5; ++run)
            for (char c : l.runs[run]) t += char32_t(c), style_of.push_back(run == 1 ? 1 : 0);
        texts.push_back(std::move(t));
        style_ofs.push_back(std::move(style_of));
    }
    FontDatabase& fonts = warm_fonts();
    std::size_t glyphs = 0;
    for (auto _ : state) {
        glyphs = 0;
        for (std::size_t i = 0; i < texts.size(); ++i) {
            std::vector<LaidGlyph> laid =
                shape_paragraph(fonts, texts[i], styles, style_ofs[i], TextDirection::Ltr);
            glyphs += laid.size();
            benchmark::DoNotOptimize(laid.data());
        }
    }
    state.counters["glyphs"] = double(glyphs); // spaces included
    state.counters["glyphs_per_s"] =
        benchmark::Counter(double(glyphs), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Shape_5000_Glyphs)->Unit(benchmark::kMillisecond);

// One line to a path, the application API: shaping and the outlines placed.
void BM_TextToPath_Line(benchmark::State& state) {
    const std::string line = page_lines()[0].all();
    const TextStyle style = page_styles()[0];
    FontDatabase& fonts = warm_fonts();
    std::size_t segments = 0;
    for (auto _ : state) {
        const Path path = text_to_path(fonts, line, style, {40, 60});
        segments = path.segment_count();
        benchmark::DoNotOptimize(path.subpaths().data());
    }
    state.counters["chars"] = double(line.size());
    state.counters["segments"] = double(segments);
}
BENCHMARK(BM_TextToPath_Line)->Unit(benchmark::kMicrosecond);

} // namespace
} // namespace casteljau

BENCHMARK_MAIN();
