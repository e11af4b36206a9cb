// The CPU time a test spends, for bounds on how much work a call does.
//
// Tests bound CPU time, not wall-clock time: on a busy machine (CI's other
// jobs, the test shards beside each other) a call waits for a core as long as
// the machine likes, but the work it does there stays the same. The count is
// the whole process's (every thread's, user and system), an upper bound on
// the calls' own, as long as the test runs nothing else meanwhile.
#pragma once

#include <sys/resource.h>

namespace casteljau::testing {

/// User plus system CPU seconds this process has used so far.
inline double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    const auto seconds = [](const timeval& t) {
        return double(t.tv_sec) + 1e-6 * double(t.tv_usec);
    };
    return seconds(u.ru_utime) + seconds(u.ru_stime);
}

} // namespace casteljau::testing
