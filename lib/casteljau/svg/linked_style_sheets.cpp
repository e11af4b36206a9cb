// Style sheets in files: those the prolog links,
//   <?xml-stylesheet href="style.css" type="text/css"?>
// (Associating Style Sheets with XML documents 1.0, 2: in the prolog only,
// their pseudo-attributes href, type, media and alternate), and those an
// @import rule at a sheet's head names (CSS Cascade 4, 2.1; css.h's
// css_imports). Their rules come before the rules of the sheet that names
// them, in order, as browsers and librsvg apply them: the linked sheets
// before every <style>.
//
// A file is found as an <image>'s is (svg/resource_url.h): relative to the
// sheet or document that names it, within the SVG's folder or
// SvgOptions::resources_dir, never the network. A data: URL's sheet is read
// in place. A var() in any sheet turns on custom properties (the reader's
// own test looks at the document's text only).
// A sheet of another type, an alternate sheet (alternate="yes") and a sheet
// whose media query does not match the picture (svg/media_query.h) are not
// applied. Problems inside a sheet file name that file and its line.
// (An @font-face rule in a file takes its sources from the SVG's folder, and
// its problems are located at the first <style>'s line: font_face.cpp.)
//
// Limits: kMaxStyleSheetFiles files a document (each @import of a file
// reads it again), @imports kMaxStyleSheetNesting deep, and all their text
// at most SvgOptions::max_attribute_bytes (what one <style> may hold); a
// file that imports itself, through any others, is a problem and is
// skipped.
#include "casteljau/io/text_file.h"
#include "casteljau/svg/detail/pseudo_attributes.h"
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/media_query.h"
#include "casteljau/svg/resource_url.h"

#include <filesystem>

namespace casteljau::svg_detail {

void Reader::linked_style_sheets(const pugi::xml_node& root) {
    // The prolog is the text before the root's start tag; read again as a
    // fragment, its processing instructions kept (the document was read
    // without them).
    const std::size_t name_at = std::size_t(std::max<std::ptrdiff_t>(offset_of(root), 0));
    const std::size_t end = text_.rfind('<', std::min(name_at, text_.size()));
    if (end == std::string_view::npos || text_.substr(0, end).find("<?") == std::string_view::npos)
        return;
    pugi::xml_document prolog;
    if (!prolog.load_buffer(text_.data(), end, pugi::parse_pi | pugi::parse_fragment)) return;
    for (const pugi::xml_node& pi : prolog.children()) {
        if (pi.type() != pugi::node_pi || std::strcmp(pi.name(), "xml-stylesheet") != 0) continue;
        std::map<std::string, std::string> a = pseudo_attributes(pi.value());
        const SvgDiagnostic where{name_, line_of(pi.offset_debug()), "xml-stylesheet", ""};
        if ((a.contains("type") && a["type"] != "text/css") || a["alternate"] == "yes") continue;
        if (a["href"].empty()) {
            problem_at({where.file, where.line, where.element, "no href; ignored"});
            continue;
        }
        const std::size_t font_faces = sheet_.font_faces().size();
        import_sheet(where, a["href"], a["media"], options_.base_dir, 1);
        load_font_faces(root, font_faces);
    }
}

// The sheet at `href` (relative to `dir`), read into the document's where
// the rule or link `where` stands; `media` the query it applies under.
void Reader::import_sheet(const SvgDiagnostic& where, const std::string& href,
                          const std::string& media, const std::string& dir, int depth) {
    const auto tell = [&](const std::string& what) {
        problem_at({where.file, where.line, where.element, "style sheet " + what});
    };
    const std::string quoted = "'" + href + "'";
    if (!media.empty()) {
        if (!media_) media_ = media_context(root_);
        std::string unknown;
        if (!media_matches(media, *media_, &unknown)) return;
    }
    if (depth > kMaxStyleSheetNesting)
        return tell(quoted + ": imports nested deeper than " +
                    std::to_string(kMaxStyleSheetNesting) + " (the limit); skipped");
    ImageBudget& budget = *options_.image_budget;
    if (++budget.sheets > kMaxStyleSheetFiles)
        return tell(quoted + ": more than " + std::to_string(kMaxStyleSheetFiles) +
                    " style sheet files in the document (the limit); skipped");
    // What is left of the bytes all sheet files may hold.
    const std::size_t left =
        options_.max_attribute_bytes - std::min(budget.sheet_bytes, options_.max_attribute_bytes);
    const auto over = [&] {
        tell(quoted + ": more than " + std::to_string(options_.max_attribute_bytes) +
             " bytes of style sheet files in the document (the limit); skipped");
    };
    std::string data_error;
    if (std::optional<DataUrl> data = parse_data_url(href, data_error)) {
        if (data->bytes.size() > left) return over();
        budget.sheet_bytes += data->bytes.size();
        const std::string css(data->bytes.begin(), data->bytes.end());
        return parse_sheet(css, {where.file, where.line, where.element, ""}, dir, depth);
    }
    if (!data_error.empty()) return tell(quoted + ": " + data_error + "; skipped");
    const ResourcePath file = resolve_resource_path(href, dir, options_.resources_dir, root_dir());
    if (!file.error.empty()) return tell(file.error + "; skipped");
    if (std::find(sheet_chain_.begin(), sheet_chain_.end(), file.path) != sheet_chain_.end())
        return tell(quoted + " imports itself; skipped");
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file.path, ec);
    if (left == 0 || (!ec && size > left)) return over();
    const TextFile f = read_text_file(file.path, left); // a file that grew meanwhile: its error
    if (!f.error.empty()) return tell(f.error + "; skipped");
    budget.sheet_bytes += f.text.size();
    sheet_chain_.push_back(file.path);
    parse_sheet(f.text, {file.path, 1, where.element, ""},
                std::filesystem::path(file.path).parent_path().string(), depth);
    sheet_chain_.pop_back();
}

} // namespace casteljau::svg_detail
