// <image> (SVG 2, 12.3; SVG 1.1, 5.7): a raster image (PNG, JPEG, GIF,
// WebP, TIFF, decoded by io/image_read.h) or an SVG document (read by this
// reader, drawn as vectors) placed in the viewport x, y, width, height.
//
// The image's own size (pixels, or the SVG's width and height) is its view
// box, fitted into the viewport by preserveAspectRatio; what falls outside
// the viewport (slice) is clipped, as the UA style sheet's overflow: hidden
// says. An absent or auto width or height is the image's own, or keeps its
// aspect ratio when the other is given. A raster image becomes a rectangle
// filled with an image paint (scene Pattern with `image`, drawn once, its
// edge pixels extended), sampled bilinearly, or the nearest pixel under
// image-rendering: optimizeSpeed, pixelated or crisp-edges.
//
// Where an image may come from (svg/resource_url.h): a data: URL, or a file
// in the SVG's folder and below, or below SvgOptions::resources_dir; never
// the network. Limits: SvgOptions::max_image_pixels for a raster image,
// max_image_nesting for SVG images inside SVG images, max_images and
// max_image_pixels_total for all that a document and its SVG images read
// (a file drawing itself under many hrefs would otherwise be read k^depth
// times), and the elements an SVG image adds count against max_elements. An image that cannot be
// used is a problem, and is not drawn. Each href is read once per document.
#include "casteljau/io/image_read.h"
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/resource_url.h"
#include "casteljau/svg/shapes.h"

#include <cctype>
#include <filesystem>

namespace casteljau::svg_detail {

namespace {

// `g` moved by `m`: every transform to device space, clips' and masks'
// content included, gets m applied after it.
Group moved(const Group& g, const Affine& m) {
    Group out{g.opacity, {}, g.blend, g.isolate, g.clip, g.mask};
    for (const Node& n : g.children) {
        if (const Shape* s = std::get_if<Shape>(&n.item)) {
            Shape c = *s;
            c.transform = m * s->transform;
            out.children.push_back(Node{std::move(c)});
        } else {
            out.children.push_back(Node{moved(std::get<Group>(n.item), m)});
        }
    }
    for (std::shared_ptr<const Mask>* mask : {&out.clip, &out.mask})
        if (*mask)
            *mask = std::make_shared<const Mask>(Mask{(*mask)->kind, moved((*mask)->content, m)});
    for (const auto& f : g.filters) {
        auto c = std::make_shared<Filter>(*f);
        c->transform = m * f->transform;
        for (Group& image : c->images) image = moved(image, m);
        c->fill_paint = moved(c->fill_paint, m);
        c->stroke_paint = moved(c->stroke_paint, m);
        out.filters.push_back(std::move(c));
    }
    return out;
}

std::size_t node_count(const Group& g) {
    std::size_t n = g.children.size();
    for (const Node& c : g.children)
        if (const Group* child = std::get_if<Group>(&c.item)) n += node_count(*child);
    return n;
}

bool has_svg_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".svg";
}

} // namespace

const Reader::ImageSource& Reader::image_source(const pugi::xml_node& n, const std::string& href) {
    if (const auto it = images_.find(href); it != images_.end()) return it->second;
    ImageSource& src = images_[href];
    read_image_source(n, href, src);
    // Read in a quiet pass (fill_box's measure), a failure's problem went
    // untold: the pass that tells reads it again.
    if (!quiet_ || src.raster || src.svg) return src;
    images_.erase(href);
    static const ImageSource none;
    return none;
}

void Reader::read_image_source(const pugi::xml_node& n, const std::string& href, ImageSource& src) {
    ImageBudget& budget = *options_.image_budget;
    if (++budget.images > options_.max_images) {
        problem(n, "more than " + std::to_string(options_.max_images) +
                       " images in the document and its SVG images (the limit); not drawn");
        return;
    }
    // What is left of the pixels all the images may decode, at most one image's limit.
    const std::size_t pixels = std::min(
        options_.max_image_pixels,
        options_.max_image_pixels_total - std::min(budget.pixels, options_.max_image_pixels_total));
    SvgOptions nested = options_;
    ++nested.image_depth;
    // Its @media answers for its own size: the size it is drawn at is not known yet.
    nested.media_size = {};
    const auto svg_from = [&](SvgResult doc) {
        for (SvgDiagnostic& w : doc.warnings)
            if (!quiet_) warnings_.push_back(std::move(w));
        if (!doc.scene) return problem(n, "the SVG image cannot be drawn: " + doc.error);
        src.width = doc.scene->width;
        src.height = doc.scene->height;
        src.svg = std::make_shared<const Group>(std::move(doc.scene->root));
    };
    const auto raster_from = [&](ImageReadResult r) {
        if (!r.image) return problem(n, "the image cannot be drawn: " + r.error);
        budget.pixels += std::size_t(r.image->width) * std::size_t(r.image->height);
        src.width = r.image->width;
        src.height = r.image->height;
        src.raster = std::move(r.image);
    };
    const auto nesting_ok = [&] {
        if (options_.image_depth < options_.max_image_nesting) return true;
        problem(n, "SVG images nested deeper than " + std::to_string(options_.max_image_nesting) +
                       " (the limit); not drawn");
        return false;
    };
    std::string error;
    if (const std::optional<DataUrl> data = parse_data_url(href, error)) {
        if (data->mime == "image/svg+xml") {
            if (nesting_ok())
                svg_from(parse_svg(
                    {reinterpret_cast<const char*>(data->bytes.data()), data->bytes.size()},
                    name_ + " (a data: URL's SVG)", nested));
        } else {
            raster_from(decode_image(data->bytes, pixels));
        }
        return;
    }
    if (!error.empty()) {
        problem(n, "href: " + error + "; not drawn");
        return;
    }
    const ResourcePath file =
        resolve_resource_path(href, options_.base_dir, options_.resources_dir, root_dir());
    if (!file.error.empty()) {
        problem(n, "href " + file.error + "; not drawn");
        return;
    }
    if (has_svg_extension(file.path)) {
        nested.base_dir.clear(); // its own folder
        if (nesting_ok()) svg_from(read_svg_file(file.path, nested));
    } else {
        raster_from(read_image_file(file.path, pixels));
    }
}

void Reader::image(const pugi::xml_node& n, const StyleState& style, const Affine& m, Group& out,
                   const Rect* given) {
    const char* href = href_of(n);
    if (!style.visible || !href[0]) return;
    const ImageSource& src = image_source(n, href);
    if (!src.raster && !src.svg) return;
    const LengthContext ctx = context(style);
    std::optional<double> w = length(n, "width", vw_, ctx), h = length(n, "height", vh_, ctx);
    if (given) w = given->width(), h = given->height();
    if (!w && !h) {
        w = src.width, h = src.height;
    } else if (!w) {
        w = *h * src.width / src.height;
    } else if (!h) {
        h = *w * src.height / src.width;
    }
    if (!non_negative(n, "width", w) || !non_negative(n, "height", h) || *w == 0 || *h == 0) return;
    const Affine port = m * Affine::translate(given ? given->min().to_vec()
                                                    : Vec2{length(n, "x", vw_, ctx).value_or(0),
                                                           length(n, "y", vh_, ctx).value_or(0)});
    const Affine fit = view_map(n, ViewBox{0, 0, src.width, src.height}, *w, *h);
    const Rect viewport{0, 0, *w, *h};
    if (src.svg) {
        Group g = moved(*src.svg, port * fit);
        elements_ += node_count(g);
        if (elements_ > options_.max_elements)
            fail(n, "more than " + std::to_string(options_.max_elements) +
                        " elements, SVG images included (the limit)");
        g.clip = rect_clip(viewport, port);
        out.children.push_back(Node{std::move(g)});
        return;
    }
    // The image's rectangle in the viewport, cut to it (slice).
    const Rect placed = Rect::from_points(fit * Point{0, 0}, fit * Point{src.width, src.height})
                            .intersected(viewport);
    if (!(placed.width() > 0 && placed.height() > 0)) return;
    auto paint = std::make_shared<Pattern>();
    paint->width = src.width;
    paint->height = src.height;
    paint->transform = fit;
    paint->image = src.raster;
    paint->repeat = false;
    paint->smooth = style.smooth_images;
    Shape s;
    s.path = rect_path(placed.x0, placed.y0, placed.width(), placed.height(), 0, 0);
    s.transform = port;
    s.fill = Fill{{0, 0, 0, 1}, nullptr, 1, FillRule::NonZero, std::move(paint)};
    s.source_line = line_of(offset_of(n));
    out.children.push_back(Node{std::move(s)});
}

} // namespace casteljau::svg_detail
