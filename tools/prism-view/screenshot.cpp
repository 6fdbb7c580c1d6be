#include "screenshot.h"

#include <chrono>
#include <ctime>

#include "io/image_writer.h"

namespace prism {

std::filesystem::path defaultScreenshotBase(const std::filesystem::path &scenePath) {
    std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm local{};
    localtime_r(&now, &local);
    char stamp[32];
    std::strftime(stamp, sizeof(stamp), "%Y%m%d-%H%M%S", &local);
    return std::filesystem::current_path() /
           ("prism-view-" + scenePath.stem().string() + "-" + stamp);
}

std::filesystem::path writeScreenshot(const std::filesystem::path &base, TracedImage traced,
                                      const RenderRecord &record) {
    OutputImage image;
    image.width = int(traced.width);
    image.height = int(traced.height);
    image.rgba = std::move(traced.rgba);
    ImageMetadata meta = renderMetadata(record);
    std::filesystem::path exr = base, png = base;
    exr.replace_extension(".exr");
    png.replace_extension(".png");
    writeImage(exr, image, meta);
    writeImage(png, image, meta);
    return exr;
}

} // namespace prism
