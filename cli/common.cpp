#include "common.h"

#include "casteljau/svg/reader.h"
#include "commands.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <map>

namespace casteljau::cli {

void add_tolerance_option(CLI::App* cmd, double& tolerance) {
    cmd->add_option("--tolerance", tolerance,
                    "Flatness bound in device pixels, in [1e-4, 1] (default 0.25)");
}

void add_flatten_options(CLI::App* cmd, FlattenOptions& o) {
    add_tolerance_option(cmd, o.tolerance);
    const std::map<std::string, FlattenMethod> methods{{"integral", FlattenMethod::Integral},
                                                       {"guided", FlattenMethod::Guided},
                                                       {"adaptive", FlattenMethod::Adaptive},
                                                       {"uniform", FlattenMethod::Uniform},
                                                       {"halving", FlattenMethod::Halving}};
    cmd->add_option("--flatten", o.method,
                    "guided (default: fastest, about 1.3x the fewest segments), integral (near "
                    "the fewest segments, every chord checked), adaptive (greedy), uniform, or "
                    "halving (textbook midpoint subdivision)")
        ->transform(CLI::CheckedTransformer(methods, CLI::ignore_case));
    cmd->add_option(
           "--segments", o.segments,
           "Uniform only: segments per curve (default: the fewest that Wang's bound guarantees "
           "meet the tolerance)")
        ->check(CLI::Range(1, kMaxUniformSegments));
}

bool check_tolerance(const char* command, double tolerance) {
    if (tolerance >= kMinTolerance && tolerance <= 1.0) return true;
    std::fprintf(stderr,
                 "casteljau %s: --tolerance %g: must be a number of device pixels in [%g, 1]\n",
                 command, tolerance, kMinTolerance);
    return false;
}

void add_svg_options(CLI::App* cmd, SvgOptions& o) {
    cmd->add_flag("--strict", o.strict,
                  "Make the first problem in an SVG file an error (exit 2, no image), instead of "
                  "a warning and the recovery the SVG and CSS specs prescribe (an invalid value "
                  "ignored, path data drawn up to its error)");
    cmd->add_option("--languages", o.languages,
                    "The user's languages for systemLanguage and <switch>, comma-separated "
                    "(default en)")
        ->delimiter(',');
    cmd->add_option_function<std::string>(
           "--color-scheme", [&o](const std::string& scheme) { o.dark = scheme == "dark"; },
           "The color scheme style sheets' @media (prefers-color-scheme) queries see: light "
           "(default) or dark")
        ->check(CLI::IsMember({"light", "dark"}));
    cmd->add_option(
           "--resources-dir", o.resources_dir,
           "A folder the files of <image>, <use> and style sheets may also come from, besides "
           "the SVG's own folder and below (never the network)")
        ->check(CLI::ExistingDirectory);
    // Fonts go to the database the reader uses when given none; it is made
    // (fontconfig's scan of the system's fonts) only when text needs it.
    cmd->add_option_function<std::vector<std::string>>(
           "--font-dir",
           [](const std::vector<std::string>& dirs) {
               for (const std::string& d : dirs) FontDatabase::system().add_font_dir(d);
           },
           "A folder of fonts for text, besides the system's (fontconfig's; FONTCONFIG_FILE "
           "chooses another configuration); may be repeated")
        ->check(CLI::ExistingDirectory);
    cmd->add_option_function<std::string>(
        "--font-family-default",
        [](const std::string& family) { FontDatabase::system().set_default_family(family); },
        "The family for text whose font-family names no font found and no family "
        "fontconfig classes as serif, monospace... (default: sans-serif)");
    // Path data is drawn up to its first error by default now: the flag of
    // that name stays, accepted and doing nothing, for the scripts that pass it.
    cmd->add_flag("--partial-path-data")->group("");
}

void Messages::warn(std::string_view what) {
    text.append("warning: ").append(what).append("\n");
    ++warnings;
}

void Messages::fail(std::string_view what) {
    text.append("error: ").append(what).append("\n");
    if (error.empty()) error = what;
}

void Messages::print() const {
    if (!text.empty()) std::fputs(text.c_str(), stderr);
}

std::optional<Scene> load_svg(const std::string& path, const SvgOptions& options, int& status,
                              Messages& log) {
    SvgResult doc = read_svg_file(path, options);
    for (const SvgDiagnostic& w : doc.warnings) log.warn(w.text());
    if (!doc.scene) {
        log.fail(doc.error);
        status = doc.io_error ? kExitFailure : kExitBadInput;
    }
    return std::move(doc.scene);
}

} // namespace casteljau::cli
