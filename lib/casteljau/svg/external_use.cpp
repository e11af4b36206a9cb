// <use> of an element in another file (SVG 2, 5.6: the href is a URL, which
// may name an element of an external resource document; without a fragment
// it names that document's root): icon sprite sheets,
// <use href="icons.svg#home"/>, drawn as librsvg and browsers draw them.
//
// The file is found as an <image>'s is (svg/resource_url.h): relative to the
// file that names it, within the SVG's folder or SvgOptions::resources_dir,
// never on the network; a data: URL is not read (browsers refuse it in
// <use> as well). Each file is read once for the whole document, by a reader
// of its own that every reader of the document shares: its style sheets
// style its elements, and the referencing document's do not reach into it
// (librsvg's behaviour; browsers differ on the second, w3c/svgwg issue 504);
// its references (gradients, markers, clips, its own <use>s, images)
// resolve in it (SVG 2, 16.2: a URL is relative to the document it is
// written in). The instance inherits the use's style, custom properties
// included, and is drawn as any use's (instancing.cpp), in the use's
// viewport; its @media is answered as this document's. Warnings inside it
// name that file and its lines. A file that names itself is the same
// document.
//
// Not done: a url() paint the instance inherits from the use
// (<use fill="url(#g)">) is looked up in the file drawn from, where CSS
// would take the using document's; and the file's gradient percentages
// are of the viewport of the use that first reads it.
//
// Limits: the files count against max_images with the images, and their
// bytes against max_file_bytes in all; files drawn from files are at most
// max_image_nesting deep; their instances' elements count against
// max_elements. An element drawn again inside its own instance, through any
// number of files, is a cycle: a problem, not drawn.
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
        resolve_resource_path(href, options_.base_dir, options_.resources_dir, root_dir());
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
    const std::vector<std::string>& chain = files_->chain;
    const std::string key = file.path + "#" + id;
    if (std::find(chain.begin(), chain.end(), key) != chain.end())
        return problem(n, quoted + " makes a cycle; skipped");
    if (chain.size() >= std::size_t(std::max(options_.max_image_nesting, 0)))
        return problem(n, "files drawn by <use> nested deeper than " +
                              std::to_string(options_.max_image_nesting) + " (the limit); skipped");
    draw_use(n, *doc, target, parent_style, style, m, out, depth, key);
}

// The other reader draws `target` in this one's place (draw_use has
// measured the use and resolved its paints here): the viewport, the counts
// against the limits and the modes pass to it, and back, and its warnings
// join this document's, in order. A reader may be drawing already (a file
// drawn from inside its own instance, through another): what it had is put
// back after.
void Reader::external_instance(Reader& doc, const std::string& key, const pugi::xml_node& target,
                               const StyleState& style, const Affine& m, ContextPaints paints,
                               const UseSize& size, Group& out, int depth) {
    struct Enter {
        Reader &to, &from;
        double vw = to.vw_, vh = to.vh_, rem = to.root_font_size_;
        bool clip_mode = to.clip_mode_, quiet = to.quiet_;
        int depth = to.depth_;
        std::vector<SvgDiagnostic> warnings; // its outer instance's, not yet passed on
        Enter(Reader& t, Reader& f, const std::string& key) : to(t), from(f) {
            to.vw_ = from.vw_, to.vh_ = from.vh_, to.root_font_size_ = from.root_font_size_;
            to.clip_mode_ = from.clip_mode_, to.quiet_ = from.quiet_, to.depth_ = from.depth_;
            to.elements_ = from.elements_, to.text_characters_ = from.text_characters_;
            warnings.swap(to.warnings_);
            from.files_->chain.push_back(key);
        }
        ~Enter() {
            from.files_->chain.pop_back();
            from.elements_ = to.elements_, from.text_characters_ = to.text_characters_;
            for (SvgDiagnostic& w : to.warnings_) from.warnings_.push_back(std::move(w));
            to.warnings_ = std::move(warnings);
            to.vw_ = vw, to.vh_ = vh, to.root_font_size_ = rem;
            to.clip_mode_ = clip_mode, to.quiet_ = quiet, to.depth_ = depth;
        }
    } const enter(doc, *this, key);
    doc.instance(target, style, m, std::move(paints), size, out, depth);
}

// The folder every file the document reads stays within (with
// resources_dir): the document read's.
const std::string& Reader::root_dir() {
    if (files_->root_dir.empty()) {
        std::error_code ec; // no current directory: "." resolves to nothing, nothing is read
        const std::filesystem::path here = std::filesystem::current_path(ec);
        files_->root_dir = !options_.base_dir.empty() ? options_.base_dir
                           : ec                       ? std::string(".")
                                                      : here.string();
    }
    return files_->root_dir;
}

// The reader of the SVG file at `path` (canonical), read on first use by
// any reader of the document; null, with a problem told at `n`, when the
// file cannot be used. The problems of its reading (its style sheets') are
// told once, by the first use that tells problems.
Reader* Reader::external_document(const pugi::xml_node& n, const std::string& path) {
    auto [it, fresh] = files_->documents.try_emplace(path);
    ExternalDocument& d = it->second;
    if (fresh) {
        ImageBudget& budget = *options_.image_budget;
        // Read, and inflated, up to what is left of the bytes all may hold.
        const std::size_t left =
            options_.max_file_bytes - std::min(budget.file_bytes, options_.max_file_bytes);
        if (++budget.images > options_.max_images) {
            d.error = "more than " + std::to_string(options_.max_images) +
                      " images and files in the document (the limit)";
        } else if (left == 0) {
            d.error = "more than " + std::to_string(options_.max_file_bytes) +
                      " bytes of files drawn from (the limit)";
        } else if (TextFile f = read_text_file(path, left); !f.error.empty()) {
            d.error = f.error;
        } else {
            d.text = std::move(f.text);
            const std::span<const unsigned char> bytes(
                reinterpret_cast<const unsigned char*>(d.text.data()), d.text.size());
            if (is_gzip(bytes)) { // SVGZ
                Gunzipped svg = gunzip(bytes, left);
                d.error = svg.error.empty() ? "" : path + ": gzip data: " + svg.error;
                d.text = std::move(svg.data);
            }
            budget.file_bytes += d.text.size();
        }
        if (d.error.empty()) load_external(d, path);
        if (!d.reader) d.text = std::string(); // nothing will read it
    }
    if (!quiet_) { // told by the first use that tells anything
        for (SvgDiagnostic& w : d.warnings) warnings_.push_back(std::move(w));
        d.warnings.clear();
    }
    if (!d.reader) problem(n, "the file cannot be drawn from: " + d.error + "; skipped");
    return d.reader.get();
}

// Reads the file's tree and style sheets with a reader of its own, which
// shares this one's files and answers @media as this document does.
void Reader::load_external(ExternalDocument& d, const std::string& path) {
    SvgOptions o = options_;
    o.base_dir = std::filesystem::path(path).parent_path().string();
    d.reader = std::make_unique<Reader>(d.text, path, o);
    Reader& r = *d.reader;
    r.own_files_.reset();
    r.files_ = files_;
    r.media_ = media_ ? *media_ : media_context(root_);
    try {
        const pugi::xml_node root = r.load();
        // Its gradients' percentages: of the viewport of the use that first
        // draws from it.
        r.vw_ = vw_, r.vh_ = vh_;
        r.index_gradients(root);
    } catch (const Failure& f) {
        d.error = f.message;
    }
    d.warnings = std::move(r.warnings_);
    r.warnings_.clear();
    if (!d.error.empty()) d.reader.reset();
}

} // namespace casteljau::svg_detail
