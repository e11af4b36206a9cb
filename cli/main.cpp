// casteljau: curves and surface patches to pixels. A thin layer over the library.
#include "commands.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    using namespace casteljau::cli;
    CLI::App app{
        "casteljau: exact, adaptive de Casteljau flattening and rendering of curves and patches"};
    app.require_subcommand(1);
    const Command flatten = add_flatten_command(app);
    const Command render = add_render_command(app);
    const Command compare = add_compare_command(app);
    const Command patch = add_patch_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return kExitBadInput;
    }
    try {
        if (app.got_subcommand("flatten")) return flatten();
        if (app.got_subcommand("render")) return render();
        if (app.got_subcommand("compare")) return compare();
        if (app.got_subcommand("patch")) return patch();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "casteljau: %s\n", e.what());
        return kExitFailure;
    }
    return kExitBadInput;
}
