// The files one `casteljau render` call draws, and where each one goes.
//
// Inputs come from the command line and from --from-list files (one path a
// line, relative to the current folder; blank lines skipped, a trailing \r
// dropped, so lists written on Windows read the same). Into a folder, an
// input goes to FOLDER/STEM.png; two inputs of the same stem would write the
// same file, so the later one fails instead (status 2, naming the earlier),
// rather than one overwriting the other, silently and in an order that
// depends on the threads.
#pragma once

#include <string>
#include <vector>

namespace casteljau::cli {

struct RenderJob {
    std::string input; ///< the path as given
    std::string where; ///< "LIST:LINE" for a listed file, "" for an argument
    std::string output;
    std::string error; ///< a problem found before rendering: the file fails with it
};

/// The job of rendering `input` (`where`: "LIST:LINE", or "" for an
/// argument), with its error when the file does not exist or is a folder:
/// one check for arguments and listed files alike, so that a missing file
/// fails alone (status 2, its record says why) and the others render.
RenderJob checked_job(const std::string& input, const std::string& where);

/// Appends the paths of the list `list` ("-": standard input) to `jobs`, as
/// checked_job makes them. False, with `error` set, when the list itself
/// cannot be read.
bool read_input_list(const std::string& list, std::vector<RenderJob>& jobs, std::string& error);

/// Sets each job's output: `output` itself, or FOLDER/STEM.png when
/// `to_folder`; a job whose output is an earlier job's gets its error.
void plan_outputs(std::vector<RenderJob>& jobs, const std::string& output, bool to_folder);

} // namespace casteljau::cli
