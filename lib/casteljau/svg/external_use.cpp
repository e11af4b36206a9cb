// <use> of an element in another file (SVG 2, 5.6: the href is a URL, which
// may name an element of an external resource document; without a fragment
// it names that document's root): icon sprite sheets,
// <use href="icons.svg#home"/>, drawn as librsvg and browsers draw them.
//
// The file is found as an <image>'s is (svg/resource_url.h): in the SVG's
// folder and below, or below SvgOptions::resources_dir, never on the
// network; a data: URL is not read (browsers refuse it in <use> as well). A
// file is read once per document, with the document's limits, by a reader
// of its own: its style sheets style its elements, and the referencing
// document's do not reach into it (librsvg's behaviour; browsers differ on
// the second, w3c/svgwg issue 504); its references (gradients, markers,
// clips, its own <use>s, images) resolve in it and its folder (SVG 2, 16.2:
// a URL is relative to the document it is written in). The instance
// inherits the use's style and is drawn as any use's (instancing.cpp), in
// the use's viewport; warnings inside it name that file and its lines. A
// file that names itself is the same document.
//
// Limits: the files count against max_images with the images; files drawn
// from files are at most max_image_nesting deep; their instances' elements
// count against max_elements. An element drawn again inside its own
// instance, through any number of files, is a cycle: a problem, not drawn.
#include "casteljau/io/gunzip.h"
#include "casteljau/io/text_file.h"
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/resource_url.h"

#include <filesystem>

namespace casteljau::svg_detail {

namespace {

// The canonical path of a file a reader was named after, or "" when its name
// is not a file's (a string read by parse_svg).
std::string canonical_or_empty(const std::string& name) {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::canonical(name, ec);
    return ec ? std::string() : p.string();
}

} // namespace

void Reader::external_use(const pugi::xml_node& n, std::string_view href,
                          const StyleState& parent_style, const StyleState& style, const Affine& m,
                          Group& out, int depth) {
    const std::string quoted = "href '" + std::string(href) + "'";
    std::string data_error;
    if (parse_data_url(href, data_error) || !data_error.empty())
        return problem(n, quoted + ": <use> reads no data: URL; skipped");
    const ResourcePath file =
        resolve_resource_path(href, options_.base_dir, options_.resources_dir);
    if (!file.error.empty()) return problem(n, "href " + file.error + "; skipped");
    const std::size_t hash = href.find('#');
    const std::string id = hash == std::string_view::npos ? "" : std::string(href.substr(hash + 1));
    if (file.path == canonical_or_empty(name_)) // this very document
        return local_use(n, id.empty() ? root_ : by_id(id), quoted, parent_style, style, m, out,
                         depth);
    Reader* doc = external_document(n, file.path);
    if (!doc) return;
    const pugi::xml_node target = id.empty() ? doc->root_ : doc->by_id(id);
    if (!target) return problem(n, quoted + " names no element; skipped");
    std::vector<std::string>& chain = *external_chain_;
    const std::string key = file.path + "#" + id;
    if (std::find(chain.begin(), chain.end(), key) != chain.end())
        return problem(n, quoted + " makes a cycle; skipped");
    if (chain.size() >= std::size_t(std::max(options_.max_image_nesting, 0)))
        return problem(n, "files drawn by <use> nested deeper than " +
                              std::to_string(options_.max_image_nesting) + " (the limit); skipped");
    // The other reader draws in this one's place: the viewport, the counts
    // against the limits and the modes pass to it, and back; its warnings
    // join this document's, in order.
    doc->vw_ = vw_, doc->vh_ = vh_;
    doc->root_font_size_ = root_font_size_;
    doc->elements_ = elements_, doc->text_characters_ = text_characters_;
    doc->clip_mode_ = clip_mode_, doc->quiet_ = quiet_, doc->depth_ = depth_;
    struct Back {
        Reader &from, &to;
        ~Back() {
            to.elements_ = from.elements_, to.text_characters_ = from.text_characters_;
            for (SvgDiagnostic& w : from.warnings_) to.warnings_.push_back(std::move(w));
            from.warnings_.clear();
            to.external_chain_->pop_back();
        }
    };
    chain.push_back(key);
    const Back back{*doc, *this};
    draw_use(n, *doc, target, parent_style, style, m, out, depth);
}

// The reader of the SVG file at `path` (canonical), read on first use; null,
// with a problem told at `n`, when the file cannot be used.
Reader* Reader::external_document(const pugi::xml_node& n, const std::string& path) {
    auto [it, fresh] = externals_.try_emplace(path);
    ExternalDocument& d = it->second;
    if (fresh) {
        if (++options_.image_budget->images > options_.max_images) {
            d.error = "more than " + std::to_string(options_.max_images) +
                      " images and files in the document (the limit)";
        } else if (TextFile f = read_text_file(path, options_.max_file_bytes); !f.error.empty()) {
            d.error = f.error;
        } else {
            d.text = std::move(f.text);
            const std::span<const unsigned char> bytes(
                reinterpret_cast<const unsigned char*>(d.text.data()), d.text.size());
            if (is_gzip(bytes)) { // SVGZ, inflated under the same limit
                Gunzipped svg = gunzip(bytes, options_.max_file_bytes);
                d.error = svg.error.empty() ? "" : path + ": gzip data: " + svg.error;
                d.text = std::move(svg.data);
            }
        }
        if (d.error.empty()) {
            SvgOptions o = options_;
            o.base_dir = std::filesystem::path(path).parent_path().string();
            d.reader = std::make_unique<Reader>(d.text, path, o);
            d.reader->external_chain_ = external_chain_;
            try {
                const pugi::xml_node root = d.reader->load();
                // Its gradients' percentages: of the viewport of the use that
                // first draws from it.
                d.reader->vw_ = vw_, d.reader->vh_ = vh_;
                d.reader->index_gradients(root);
            } catch (const Failure& f) {
                d.error = f.message;
                d.reader.reset();
            }
        }
    }
    if (!d.reader) problem(n, "the file cannot be drawn from: " + d.error + "; skipped");
    return d.reader.get();
}

} // namespace casteljau::svg_detail
