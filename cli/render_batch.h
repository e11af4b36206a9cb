// Rendering the files of one `casteljau render` call on every thread.
#pragma once

#include "casteljau/paint/color.h"
#include "render_file.h"
#include "render_inputs.h"

#include <functional>
#include <string>
#include <vector>

namespace casteljau::cli {

/// Takes the --stats records, one a file, in the order of `jobs`.
using RecordSink = std::function<void(const std::string& record)>;

/// Renders every job on all_threads(a) threads (see render_batch.cpp); prints
/// each file's messages in one piece as it finishes, and a progress line
/// when `progress`. Returns the worst status.
int render_batch(const RenderArgs& a, Premul background, const std::vector<RenderJob>& jobs,
                 bool progress, const RecordSink& sink);

} // namespace casteljau::cli
