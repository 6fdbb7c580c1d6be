#pragma once
// Images written on a thread of their own while the caller goes on tracing the next frame: in a
// frame range the EXR encode and the disk no longer add to each frame's time (issue 32). Each
// image is written atomically (writeImage), in the order pushed.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include "io/image_writer.h"

namespace prism {

class ImageWriteQueue {
public:
    // At most `maxWaiting` images wait to be written (each holds a frame's pixels): push blocks
    // past that, so a slow disk slows the render instead of filling memory.
    explicit ImageWriteQueue(size_t maxWaiting = 2);
    // Waits for the images pushed to be written; errors are lost here: call finish() first.
    ~ImageWriteQueue();
    ImageWriteQueue(const ImageWriteQueue &) = delete;
    ImageWriteQueue &operator=(const ImageWriteQueue &) = delete;

    // Queues `image` for `path`. Throws the error of an earlier write, if one failed: a range
    // stops at the first image it cannot write.
    void push(std::filesystem::path path, OutputImage image, ImageMetadata meta);
    // Waits until every image pushed is on disk; throws the first write's error, if any.
    void finish();
    // Milliseconds each finished write took, in the order pushed.
    std::vector<double> writeMs() const;

private:
    struct Job {
        std::filesystem::path path;
        OutputImage image;
        ImageMetadata meta;
    };
    void run(std::stop_token stop);
    void rethrowFailure(); // with mutex_ held

    size_t maxWaiting_;
    mutable std::mutex mutex_;
    std::condition_variable_any changed_;
    std::deque<Job> jobs_;
    bool writing_ = false; // the front job is being written
    std::exception_ptr failure_;
    std::vector<double> writeMs_;
    std::jthread worker_; // last: started once the rest is made, joined first
};

} // namespace prism
