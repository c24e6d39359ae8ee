#pragma once

// A FIFO for the tests that readers refuse one without opening it.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>

namespace texsplat::test {

/// A FIFO at `path` (replacing what is there), removed again by the destructor. Opening a FIFO
/// for reading blocks until a writer comes: should a reader open it after all, a watchdog thread
/// opens and closes the write end, so the reader sees an empty file and the test fails instead
/// of hanging.
class TestFifo {
public:
    explicit TestFifo(std::string path) : mPath(std::move(path)) {
        std::filesystem::remove(mPath);
        if (mkfifo(mPath.c_str(), 0600) != 0) {
            throw std::runtime_error("TestFifo: cannot make " + mPath);
        }
        mWatchdog = std::thread([this] {
            while (!mDone) {
                // Succeeds only while a reader waits in open(); it then sees end of file.
                const int fd = open(mPath.c_str(), O_WRONLY | O_NONBLOCK);
                if (fd >= 0) {
                    close(fd);
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            }
        });
    }
    TestFifo(const TestFifo&) = delete;
    TestFifo& operator=(const TestFifo&) = delete;
    ~TestFifo() {
        mDone = true;
        mWatchdog.join();
        std::filesystem::remove(mPath);
    }

    const std::string& path() const { return mPath; }

private:
    std::string mPath;
    std::atomic<bool> mDone{false};
    std::thread mWatchdog;
};

} // namespace texsplat::test
