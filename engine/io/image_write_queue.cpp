#include "io/image_write_queue.h"

#include "core/timer.h"

namespace prism {

ImageWriteQueue::ImageWriteQueue(size_t maxWaiting)
    : maxWaiting_(maxWaiting == 0 ? 1 : maxWaiting),
      worker_([this](std::stop_token stop) { run(stop); }) {}

ImageWriteQueue::~ImageWriteQueue() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return jobs_.empty() || failure_; });
    lock.unlock();
    worker_.request_stop();
    changed_.notify_all();
}

void ImageWriteQueue::rethrowFailure() {
    if (failure_)
        std::rethrow_exception(failure_);
}

void ImageWriteQueue::push(std::filesystem::path path, OutputImage image, ImageMetadata meta) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return jobs_.size() < maxWaiting_ + (writing_ ? 1 : 0) || failure_; });
    rethrowFailure();
    jobs_.push_back(Job{std::move(path), std::move(image), std::move(meta)});
    changed_.notify_all();
}

void ImageWriteQueue::finish() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return jobs_.empty() || failure_; });
    rethrowFailure();
}

std::vector<double> ImageWriteQueue::writeMs() const {
    std::lock_guard lock(mutex_);
    return writeMs_;
}

void ImageWriteQueue::run(std::stop_token stop) {
    std::unique_lock lock(mutex_);
    while (true) {
        changed_.wait(lock, stop, [&] { return !jobs_.empty() && !failure_; });
        if (stop.stop_requested() && (jobs_.empty() || failure_))
            return;
        writing_ = true;
        Job &job = jobs_.front();
        lock.unlock();
        std::exception_ptr failed;
        Timer timer;
        try {
            writeImage(job.path, job.image, job.meta);
        } catch (...) {
            failed = std::current_exception();
        }
        double ms = timer.elapsedMs();
        lock.lock();
        writing_ = false;
        if (failed)
            failure_ = failed;
        else
            writeMs_.push_back(ms);
        jobs_.pop_front();
        changed_.notify_all();
    }
}

} // namespace prism
