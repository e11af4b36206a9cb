// The memory gate across fork(): a child forked while another thread is
// through the gate can still go through it (the fork waits for the gate).
#include "casteljau/render/memory_gate.h"

#include <atomic>
#include <chrono>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace casteljau {
namespace {

TEST(MemoryGate, AChildForkedWhileAnotherThreadIsThroughTheGateCanEnterIt) {
    std::atomic<bool> inside{false};
    std::thread holder([&] {
        memory_gate::enter();
        inside = true;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        memory_gate::leave();
    });
    while (!inside) std::this_thread::yield();
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        alarm(10); // a hang guard: a gate inherited held would wait forever
        memory_gate::enter();
        memory_gate::leave();
        _exit(memory_gate::depth() == 0 ? 0 : 3);
    }
    holder.join();
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << "status " << status << " (SIGALRM: the child waited on the gate)";
}

TEST(MemoryGate, AThreadThroughTheGateCanFork) {
    memory_gate::enter();
    const pid_t pid = fork(); // the handler must not wait on the gate this thread holds
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        alarm(10);
        memory_gate::leave();
        memory_gate::enter();
        memory_gate::leave();
        _exit(0);
    }
    memory_gate::leave();
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

} // namespace
} // namespace casteljau
