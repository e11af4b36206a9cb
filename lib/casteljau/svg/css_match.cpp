// CSS selector matching (Selectors 4) and the cascade order of the
// matching rules (CSS Cascade 4, 6.4 specificity, 6.5 order of appearance).
//
// The index: each selector is filed under the id, else the first class,
// else the type of its rightmost compound (the subject), else under
// "universal", as browsers file their rules; an element looks up its id, each
// of its classes and its name, and tests those lists and the universal one.
// With k classes, that is k + 2 hash lookups, and only selectors whose
// subject could match are tested.
//
// A selector is matched right to left (compounds[last] at the element,
// then leftwards along the combinators). The search for a descendant
// combinator's left side walks up the ancestors; a failure that no other
// choice further out can repair ("global": every element the outer loops
// would try next has a subset of the ancestors just searched) ends the
// whole match at once, the rule WebKit and Servo use. With descendant and
// child combinators a test is then O(depth x compounds) compound tests.
//
// Sibling positions (:nth-child(), :nth-of-type(), :last-of-type ...) are
// numbered once per parent, all its children at once, so each is O(1)
// amortised instead of a walk over the siblings. A `~` combinator asks
// "does an earlier sibling match the left side?": the first child of the
// parent that matches it is found once per (parent, selector, compound)
// and cached, so a long list of siblings is scanned once, not once per
// sibling (up to kMaxCached entries; past that, the walk is done each time,
// still within the work limit). Recursion is bounded by kCssMaxCompounds
// times kCssMaxNesting + 1 frames: selectors longer or deeper are not parsed.
#include "casteljau/svg/css.h"
#include "casteljau/svg/detail/css_selector.h"

#include <algorithm>
#include <functional>
#include <unordered_map>
#include <utility>

namespace casteljau {

using css_detail::AttrOp;
using css_detail::Combinator;
using css_detail::Complex;
using css_detail::Compound;
using css_detail::Simple;
using css_detail::Specificity;

void css_detail::SheetData::add(std::vector<Complex> selectors, std::uint32_t rule) {
    for (Complex& c : selectors) {
        const auto index = std::uint32_t(entries.size());
        const Compound& subject = c.compounds.back();
        const Simple *id = nullptr, *cls = nullptr;
        for (const Simple& s : subject.simples) {
            if (s.kind == Simple::Kind::Id && !id) id = &s;
            if (s.kind == Simple::Kind::Class && !cls) cls = &s;
        }
        if (id)
            by_id[id->name].push_back(index);
        else if (cls)
            by_class[cls->name].push_back(index);
        else if (!subject.type.empty())
            by_type[subject.type].push_back(index);
        else
            universal.push_back(index);
        entries.push_back({std::move(c), rule});
    }
}

namespace {

using Node = CssTree::Node;

// CSS whitespace, which separates the words of class="a b" and [a~=b].
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

bool equal(std::string_view a, std::string_view b, bool ignore_case) {
    if (!ignore_case) return a == b;
    const auto fold = [](char c) { return c >= 'A' && c <= 'Z' ? char(c | 0x20) : c; };
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                              [&](char x, char y) { return fold(x) == fold(y); });
}

bool has_word(std::string_view list, std::string_view word, bool ignore_case) {
    while (!list.empty()) {
        while (!list.empty() && is_space(list.front())) list.remove_prefix(1);
        std::size_t n = 0;
        while (n < list.size() && !is_space(list[n])) ++n;
        if (n > 0 && equal(list.substr(0, n), word, ignore_case)) return true;
        list.remove_prefix(n);
    }
    return false;
}

// Selectors 4, 6.1 and 6.2: the operators that match a part of the value
// match nothing with an empty value, as ~= does with one holding a space.
bool attribute_matches(const Simple& s, const char* attribute) {
    if (!attribute) return false;
    const std::string_view v = attribute, want = s.value;
    const bool i = s.ignore_case;
    switch (s.op) {
    case AttrOp::Exists:
        return true;
    case AttrOp::Equals:
        return equal(v, want, i);
    case AttrOp::Includes:
        return !want.empty() && std::none_of(want.begin(), want.end(), is_space) &&
               has_word(v, want, i);
    case AttrOp::DashMatch:
        return equal(v, want, i) || (v.size() > want.size() && v[want.size()] == '-' &&
                                     equal(v.substr(0, want.size()), want, i));
    case AttrOp::Prefix:
        return !want.empty() && v.size() >= want.size() && equal(v.substr(0, want.size()), want, i);
    case AttrOp::Suffix:
        return !want.empty() && v.size() >= want.size() &&
               equal(v.substr(v.size() - want.size()), want, i);
    case AttrOp::Substring:
        for (std::size_t at = 0; !want.empty() && at + want.size() <= v.size(); ++at)
            if (equal(v.substr(at, want.size()), want, i)) return true;
        return false;
    }
    return false;
}

// Is `index` (1-based) of the form a n + b for some n >= 0?
bool nth(std::int64_t a, std::int64_t b, std::int64_t index) {
    if (a == 0) return index == b;
    const std::int64_t d = index - b;
    return d % a == 0 && d / a >= 0;
}

} // namespace

struct CssMatcher::State {
    enum class Result { Match, Fail, Global };
    struct Position {
        std::uint32_t index = 1, count = 1, type_index = 1, type_count = 1; // 1-based
    };
    struct Key {
        Node parent;
        const Complex* selector;
        std::size_t compound;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            const std::size_t h = std::hash<const void*>{}(k.parent);
            return h ^ (std::hash<const void*>{}(k.selector) + 0x9e3779b97f4a7c15u + (h << 6) +
                        (h >> 2) + k.compound);
        }
    };
    // Enough for every parent of a million-element document under a few
    // `~` selectors; some 50 MB.
    static constexpr std::size_t kMaxCached = std::size_t(1) << 20;

    const css_detail::SheetData& data;
    const CssTree& tree;
    std::uint64_t max_work, work = 0;
    bool exhausted = false;
    std::unordered_map<Node, Position> positions;
    // The 1-based position of the first child of `parent` matched by
    // compounds [0, compound] of `selector`; 0 for none.
    std::unordered_map<Key, std::uint32_t, KeyHash> first_match;
    std::vector<std::pair<Specificity, std::uint32_t>> matched; // (specificity, rule)
    std::vector<std::string_view> classes;
    std::vector<Node> children;
    std::unordered_map<std::string_view, std::uint32_t> of_type;

    State(const css_detail::SheetData& d, const CssTree& t, std::uint64_t max)
        : data(d), tree(t), max_work(max) {}

    const Position& position(Node e) {
        if (const auto it = positions.find(e); it != positions.end()) return it->second;
        const Node parent = tree.parent(e);
        if (!parent) return positions[e]; // the root is its own only sibling
        children.clear();
        of_type.clear();
        for (Node k = tree.first_child(parent); k; k = tree.next_sibling(k)) children.push_back(k);
        work += children.size();
        for (std::size_t i = 0; i < children.size(); ++i)
            positions[children[i]] = {std::uint32_t(i + 1), std::uint32_t(children.size()),
                                      ++of_type[tree.name(children[i])], 0};
        for (const Node k : children) positions[k].type_count = of_type[tree.name(k)];
        return positions[e];
    }

    bool simple(const Simple& s, Node e) {
        using K = Simple::Kind;
        switch (s.kind) {
        case K::Id: {
            const char* id = tree.attribute(e, "id");
            return id && s.name == id;
        }
        case K::Class: {
            const char* cls = tree.attribute(e, "class");
            return cls && has_word(cls, s.name, false);
        }
        case K::Attr:
            return attribute_matches(s, tree.attribute(e, s.name.c_str()));
        case K::Root:
            return !tree.parent(e);
        case K::Empty:
            return tree.empty(e);
        case K::FirstChild:
            return !tree.previous_sibling(e);
        case K::LastChild:
            return !tree.next_sibling(e);
        case K::OnlyChild:
            return !tree.previous_sibling(e) && !tree.next_sibling(e);
        case K::Nth: {
            const Position& p = position(e);
            const std::uint32_t index = s.of_type ? p.type_index : p.index;
            const std::uint32_t count = s.of_type ? p.type_count : p.count;
            return nth(s.a, s.b, s.from_end ? count - index + 1 : index);
        }
        case K::Link:
            return tree.name(e) == "a" &&
                   (tree.attribute(e, "href") || tree.attribute(e, "xlink:href"));
        case K::Never:
            return false;
        case K::Not:
            return !any(s.args, e);
        case K::Is:
            return any(s.args, e);
        }
        return false;
    }

    bool any(const std::vector<Complex>& selectors, Node e) {
        for (const Complex& c : selectors)
            if (match_at(c, c.compounds.size() - 1, e) == Result::Match) return true;
        return false;
    }

    bool compound(const Compound& c, Node e) {
        if (++work > max_work) exhausted = true;
        if (exhausted || (!c.type.empty() && tree.name(e) != c.type)) return false;
        for (const Simple& s : c.simples)
            if (!simple(s, e)) return false;
        return true;
    }

    // Do compounds [0, i] of `s` match with compound i at `e`?
    Result match_at(const Complex& s, std::size_t i, Node e) {
        if (!compound(s.compounds[i], e)) return exhausted ? Result::Global : Result::Fail;
        if (i == 0) return Result::Match;
        switch (s.compounds[i].left) {
        case Combinator::Child: {
            const Node parent = tree.parent(e);
            return parent ? match_at(s, i - 1, parent) : Result::Global;
        }
        case Combinator::Descendant:
            for (Node p = tree.parent(e); p; p = tree.parent(p))
                if (const Result r = match_at(s, i - 1, p); r != Result::Fail) return r;
            return Result::Global;
        case Combinator::Next: {
            const Node previous = tree.previous_sibling(e);
            return previous ? match_at(s, i - 1, previous) : Result::Fail;
        }
        case Combinator::Subsequent:
            // Exact: so no failure kind to pass on, and a plain failure is
            // always safe (it only makes the outer loops keep looking).
            if (earlier_sibling_matches(s, i - 1, e)) return Result::Match;
            return exhausted ? Result::Global : Result::Fail;
        }
        return Result::Fail;
    }

    bool earlier_sibling_matches(const Complex& s, std::size_t i, Node e) {
        const Node parent = tree.parent(e);
        if (!parent) return false;
        const Key key{parent, &s, i};
        std::uint32_t first = 0;
        if (const auto it = first_match.find(key); it != first_match.end()) {
            first = it->second;
        } else if (first_match.size() < kMaxCached) {
            std::uint32_t n = 0;
            for (Node k = tree.first_child(parent); k && !first; k = tree.next_sibling(k)) {
                ++n;
                if (match_at(s, i, k) == Result::Match) first = n;
                if (exhausted) return false;
            }
            first_match.emplace(key, first);
        } else {
            for (Node k = tree.previous_sibling(e); k && !exhausted; k = tree.previous_sibling(k))
                if (match_at(s, i, k) == Result::Match) return true;
            return false;
        }
        return first != 0 && first < position(e).index;
    }
};

CssMatcher::CssMatcher(const StyleSheet& sheet, const CssTree& tree, std::uint64_t max_work)
    : state_(std::make_unique<State>(*sheet.data_, tree, max_work)) {}
CssMatcher::~CssMatcher() = default;

std::uint64_t CssMatcher::work() const { return state_->work; }

bool CssMatcher::match(CssTree::Node element, std::vector<const CssDeclaration*>& out) {
    State& st = *state_;
    const css_detail::SheetData& d = st.data;
    out.clear();
    if (st.exhausted) return false;
    st.matched.clear();
    const auto test = [&](const css_detail::Buckets& buckets, std::string_view key) {
        if (const auto it = buckets.find(key); it != buckets.end())
            for (const std::uint32_t k : it->second) {
                const css_detail::SheetData::Entry& entry = d.entries[k];
                const Complex& s = entry.selector;
                if (st.match_at(s, s.compounds.size() - 1, element) == State::Result::Match)
                    st.matched.emplace_back(s.specificity, entry.rule);
            }
    };
    if (!d.by_id.empty())
        if (const char* id = st.tree.attribute(element, "id")) test(d.by_id, id);
    if (!d.by_class.empty())
        if (const char* cls = st.tree.attribute(element, "class")) {
            // Each class once: class="a a" must not test the .a rules twice.
            st.classes.clear();
            std::string_view list = cls;
            while (!list.empty()) {
                std::size_t n = 0;
                while (n < list.size() && !is_space(list[n])) ++n;
                if (n > 0) st.classes.push_back(list.substr(0, n));
                list.remove_prefix(std::min(list.size(), n + 1));
            }
            std::sort(st.classes.begin(), st.classes.end());
            st.classes.erase(std::unique(st.classes.begin(), st.classes.end()), st.classes.end());
            for (const std::string_view c : st.classes) test(d.by_class, c);
        }
    if (!d.by_type.empty()) test(d.by_type, st.tree.name(element));
    for (const std::uint32_t k : d.universal) {
        const Complex& s = d.entries[k].selector;
        if (st.match_at(s, s.compounds.size() - 1, element) == State::Result::Match)
            st.matched.emplace_back(s.specificity, d.entries[k].rule);
    }
    if (st.exhausted) return false;
    // A rule matched through several selectors of its list counts once, at
    // its highest specificity; then the cascade order.
    auto& m = st.matched;
    std::sort(m.begin(), m.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second < b.second : a.first > b.first;
    });
    m.erase(std::unique(m.begin(), m.end(),
                        [](const auto& a, const auto& b) { return a.second == b.second; }),
            m.end());
    std::sort(m.begin(), m.end());
    for (const auto& [specificity, rule] : m) {
        const css_detail::SheetData::Rule& r = d.rules[rule];
        for (std::uint32_t k = r.first; k < r.first + r.count; ++k)
            out.push_back(&d.declarations[k]);
    }
    return true;
}

} // namespace casteljau
