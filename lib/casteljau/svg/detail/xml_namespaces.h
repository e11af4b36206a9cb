// Namespace prefixes of their own for SVG and XLink (Namespaces in XML 1.0):
// <svg:svg xmlns:svg="http://www.w3.org/2000/svg"> as XSLT and XHTML
// documents write it, <ns0:svg xmlns:ns0=...> as Python's ElementTree does
// unless told otherwise, an href in a prefix other than xlink. Browsers and
// librsvg read names by namespace, not by prefix; pugixml reads names as
// written. So, once the document is parsed, the elements of the SVG
// namespace under another prefix take their plain (local) names, and the
// attributes of the XLink namespace the prefix "xlink", which is what the
// reader looks for (an attribute in the SVG namespace, svg:fill, is not
// fill, and stays foreign). Other namespaces keep their prefixes: their
// elements are foreign, and skipped; so are the unprefixed elements under a
// default namespace declared other than SVG's (xmlns="urn:x"), which take a
// prefix. Declarations are scoped as the specification says (a declaration
// holds for its element and what it holds, an inner one hiding an outer one).
#pragma once

#include <cstddef>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <unordered_map>

namespace casteljau::svg_detail {

/// Whether `text` declares a prefix that normalize_namespaces renames: one
/// for the SVG namespace (but "svg" unless "<svg:" occurs: Inkscape declares
/// it in every file and uses it nowhere), or one other than "xlink" for
/// XLink's, or a default namespace other than SVG's. A quick test, so that
/// most documents are not walked.
bool declares_own_prefixes(std::string_view text);

/// An element normalize_namespaces renamed: its name as written and where it
/// starts in the text (pugixml forgets a renamed node's offset, which every
/// warning's line comes from).
struct RenamedElement {
    std::string written;   ///< the qualified name in the file
    std::ptrdiff_t offset; ///< pugixml's offset_debug() before the renaming
};
/// The renamed elements, by node (pugi::xml_node::internal_object()).
using RenamedElements = std::unordered_map<const void*, RenamedElement>;

/// Renames the document's SVG elements and XLink attributes written with
/// prefixes of their own to the reader's names (top of the file); returns
/// the elements renamed.
RenamedElements normalize_namespaces(pugi::xml_document& doc);

} // namespace casteljau::svg_detail
