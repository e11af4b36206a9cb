// Internal general entities (XML 1.0, 4.1 to 4.4): declared in a document's
// DOCTYPE, <!ENTITY name "replacement text">, and referred to as &name; in
// its content and attribute values, where the reference is replaced by the
// text. pugixml reads a DOCTYPE without acting on it, so the references
// are expanded here, on the document's text, before it is parsed. Adobe
// Illustrator's Save As SVG writes its files so (Export As does not): its
// namespaces are entities
// (<!ENTITY ns_ai "http://ns.adobe.com/AdobeIllustrator/10.0/">,
// xmlns:i="&ns_ai;"), and browsers and librsvg read them.
//
// What is expanded: references to general entities declared in the internal
// subset, in content and in attribute values, not in comments, CDATA
// sections or processing instructions (where & is not markup); references in
// a replacement text, in turn (depth-first, up to kMaxEntityNesting). What
// is not: the predefined entities and character references (pugixml's),
// references to names declared nowhere (left as written), parameter
// entities (%name;, the DTD's own). External entities (SYSTEM or PUBLIC)
// are never fetched: a reference to one is an error, as is a replacement
// that refers to itself or that adds more than the caller's limit in all
// (an entity bomb: ten entities of ten references each add 10^10 bytes).
//
// The DOCTYPE itself is left as it is, so that lines keep their numbers
// wherever replacement texts hold no line break (Illustrator's never do).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace casteljau {

/// Replacement texts within replacement texts, at most.
inline constexpr int kMaxEntityNesting = 16;

/// The outcome of expand_entities.
struct EntityExpansion {
    /// Whether a DOCTYPE was found and read. The reader refuses a document
    /// whose DOCTYPE pugixml finds and this did not (one in UTF-16: its
    /// entities would go unexpanded).
    bool doctype = false;
    /// Whether the document refers to any entity it declares; when not,
    /// `text` is empty and the document is read as it is.
    bool changed = false;
    std::string text;       ///< the document with its references replaced
    std::string error;      ///< "" or what is wrong, and then nothing else is set
    std::size_t offset = 0; ///< where in the document the error is
};

/// Expands the internal general entities `doc` declares (top of the file),
/// adding at most `max_added` bytes in all.
EntityExpansion expand_entities(std::string_view doc, std::size_t max_added);

} // namespace casteljau
