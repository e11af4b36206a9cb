#include "render_inputs.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <unordered_map>

namespace casteljau::cli {

namespace {

namespace fs = std::filesystem;

// "LIST:LINE: PATH" or "PATH": where a job's messages start.
std::string located(const RenderJob& job) {
    return job.where.empty() ? job.input : job.where + ": " + job.input;
}

bool read_lines(std::istream& in, const std::string& name, std::vector<RenderJob>& jobs) {
    std::string line;
    for (long n = 1; std::getline(in, line); ++n) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (n == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3); // a UTF-8 byte order mark
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        jobs.push_back(checked_job(line, name + ":" + std::to_string(n)));
    }
    return !in.bad();
}

} // namespace

RenderJob checked_job(const std::string& input, const std::string& where) {
    RenderJob job{input, where, "", ""};
    std::error_code ec;
    if (!fs::exists(input, ec))
        job.error = located(job) + ": does not exist";
    else if (fs::is_directory(input, ec))
        job.error = located(job) + ": is a folder, not an SVG file";
    return job;
}

bool read_input_list(const std::string& list, std::vector<RenderJob>& jobs, std::string& error) {
    if (list == "-") {
        if (read_lines(std::cin, "<stdin>", jobs)) return true;
        error = "--from-list -: cannot read the standard input";
        return false;
    }
    std::error_code ec;
    if (fs::is_directory(list, ec)) {
        error = "--from-list " + list + ": is a folder, not a list of files";
        return false;
    }
    std::ifstream in(list);
    if (!in) {
        error = "--from-list " + list + ": cannot read: " + std::strerror(errno);
        return false;
    }
    if (read_lines(in, list, jobs)) return true;
    error = "--from-list " + list + ": read failed: " + std::strerror(errno);
    return false;
}

void plan_outputs(std::vector<RenderJob>& jobs, const std::string& output, bool to_folder) {
    std::unordered_map<std::string, const RenderJob*> taken;
    for (RenderJob& job : jobs) {
        job.output =
            to_folder ? (fs::path(output) / fs::path(job.input).stem()).string() + ".png" : output;
        if (!job.error.empty()) continue; // it writes nothing
        const auto [it, first] = taken.emplace(job.output, &job);
        if (!first)
            job.error = located(job) + ": its output " + job.output + " is already that of " +
                        located(*it->second) +
                        " (the same file name): rename one, or render them separately";
    }
}

} // namespace casteljau::cli
