// prism-gridbench: how long each grid takes to build, what it holds and what it costs a ray, set
// beside Intel Embree's BVH build of the same primitives (issue 8's yardstick). CPU only.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "accel/grid.h"
#include "accel/walk_counts.h"
#include "command_line.h"
#include "core/error.h"
#include "core/median.h"
#include "core/parallel_for.h"
#include "core/timer.h"
#include "embree_baseline.h"
#include "scene/scene_loader.h"
#include "scene/scene_origin.h"

namespace prism {
namespace {

struct Row {
    std::string scene, structure, layout;
    uint64_t primitives = 0, cells = 0, bytes = 0;
    uint32_t maxPerCell = 0, depth = 0;
    WalkCounts walk;
    double buildMs = 0.0; // median
    std::vector<double> buildsMs;
    std::string choice;
    std::string digest; // of the grid's arrays: equal digests, byte-identical grids
};

// FNV-1a (64 bits) over the arrays the tracer reads, in order, to tell whether two builds (two
// commits, two thread counts) made the same grid.
std::string gridDigest(const Grid &grid) {
    uint64_t hash = 14695981039346656037ull;
    auto add = [&](const void *data, size_t bytes) {
        const unsigned char *p = static_cast<const unsigned char *>(data);
        for (size_t i = 0; i < bytes; ++i)
            hash = (hash ^ p[i]) * 1099511628211ull;
    };
    add(grid.cellStart.data(), 4 * grid.cellStart.size());
    add(grid.cellPrimitives.data(), 4 * grid.cellPrimitives.size());
    add(grid.entries.data(), 4 * grid.entries.size());
    add(grid.cellBoxes.data(), 16 * grid.cellBoxes.size());
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)hash);
    return text;
}

// A --grids value: a --grid value, with "+lean" after it for the lean build (GridOptions::effort:
// the adaptive grid's cells not expanded).
GridOptions benchGridOptions(const std::string &text) {
    constexpr std::string_view kLean = "+lean";
    std::string_view grid = text;
    bool lean = grid.ends_with(kLean);
    if (lean)
        grid.remove_suffix(kLean.size());
    GridOptions options = parseGridOption(grid);
    if (lean)
        options.effort = GridOptions::Effort::Lean;
    return options;
}

Row measureGrid(const Scene &scene, const std::string &name, const std::string &gridText,
                uint32_t runs) {
    GridOptions options = benchGridOptions(gridText);
    Row row;
    row.scene = name;
    row.structure = gridText;
    row.primitives = scene.finitePrimitiveCount();
    Grid grid;
    for (uint32_t r = 0; r < runs; ++r) {
        Timer timer;
        grid = buildGrid(scene, options);
        row.buildsMs.push_back(timer.elapsedMs());
    }
    row.buildMs = median(row.buildsMs);
    row.layout = (grid.adaptive() ? "adaptive " : "") + std::to_string(grid.resolution.x) + "x" +
                 std::to_string(grid.resolution.y) + "x" + std::to_string(grid.resolution.z);
    row.cells = grid.cellCount();
    row.bytes = grid.bytes();
    row.maxPerCell = grid.maxPerCell;
    row.depth = grid.depth;
    row.walk = countWalks(scene, grid, 4.0 / 3.0);
    row.choice = grid.choice;
    row.digest = gridDigest(grid);
    return row;
}

Row measureEmbree(const Scene &scene, const std::string &name, uint32_t runs) {
    Row row;
    row.scene = name;
    row.structure = "embree";
    row.layout = "BVH (rtcCommitScene)";
    row.primitives = scene.finitePrimitiveCount();
    for (uint32_t r = 0; r < runs; ++r)
        row.buildsMs.push_back(EmbreeBaseline(scene, 1, 1).build().commitMs);
    row.buildMs = median(row.buildsMs);
    return row;
}

std::string number(double value, const char *format) {
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

void printTable(const std::vector<Row> &rows, uint32_t runs) {
    std::printf("Build times: median of %u builds, %u threads. cells/ray, tests/ray: the tracer's "
                "work per primary ray, counted on the CPU (48x36 camera rays).\n\n",
                runs, parallelThreadCount());
    std::printf("| scene | primitives | grid | layout | cells | bytes/prim | max/cell | depth | "
                "cells/ray | tests/ray | build ms | vs Embree |\n"
                "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Row &r : rows) {
        double embree = 0.0;
        for (const Row &e : rows)
            if (e.scene == r.scene && e.structure == "embree")
                embree = e.buildMs;
        std::string grid[6]; // cells .. tests/ray: blank for Embree's row
        if (r.structure != "embree") {
            grid[0] = std::to_string(r.cells);
            grid[1] = std::to_string(r.bytes / std::max<uint64_t>(1, r.primitives));
            grid[2] = std::to_string(r.maxPerCell);
            grid[3] = std::to_string(r.depth);
            grid[4] = number(r.walk.cellsPerRay, "%.2f");
            grid[5] = number(r.walk.testsPerRay, "%.2f");
        }
        std::string ratio = embree > 0.0 ? number(r.buildMs / embree, "%.2fx") : "";
        std::printf("| %s | %llu | %s | %s | %s | %s | %s | %s | %s | %s | %.1f | %s |\n",
                    r.scene.c_str(), (unsigned long long)r.primitives, r.structure.c_str(),
                    r.layout.c_str(), grid[0].c_str(), grid[1].c_str(), grid[2].c_str(),
                    grid[3].c_str(), grid[4].c_str(), grid[5].c_str(), r.buildMs, ratio.c_str());
    }
    std::printf("\n");
    for (const Row &r : rows)
        if (!r.choice.empty())
            std::printf("%s, auto: %s\n", r.scene.c_str(), r.choice.c_str());
    for (const Row &r : rows)
        if (!r.digest.empty())
            std::printf("%s, %s: arrays' digest %s\n", r.scene.c_str(), r.structure.c_str(),
                        r.digest.c_str());
}

nlohmann::json toJson(const Row &r) {
    return {{"scene", r.scene},
            {"grid", r.structure},
            {"layout", r.layout},
            {"primitives", r.primitives},
            {"cells", r.cells},
            {"bytes", r.bytes},
            {"max_per_cell", r.maxPerCell},
            {"depth", r.depth},
            {"cells_per_primary_ray", r.walk.cellsPerRay},
            {"tests_per_primary_ray", r.walk.testsPerRay},
            {"build_ms_median", r.buildMs},
            {"build_ms", r.buildsMs},
            {"choice", r.choice},
            {"digest", r.digest}};
}

} // namespace
} // namespace prism

int main(int argc, char **argv) {
    using namespace prism;
    CLI::App app{"prism-gridbench: times grid builds (median of --runs) and reports what each grid "
                 "holds and costs a camera ray, beside Embree's BVH build of the same primitives "
                 "where Embree is installed. CPU only."};
    app.set_version_flag("--version", "prism-gridbench 0.1.0");
    std::vector<std::string> scenes;
    std::string gridList = "regular,adaptive,auto", jsonPath;
    uint32_t runs = 5;
    bool noEmbree = false;
    unsigned threads = 0;
    app.add_option("SCENES", scenes, "Scene files")->required()->check(CLI::ExistingFile);
    app.add_option("--grids", gridList,
                   "Comma-separated --grid values to build: auto, regular, adaptive, off, N, "
                   "NxNyNz; +lean after one (adaptive+lean) builds it lean, as prism-render "
                   "does for one image of a big mesh: the adaptive grid's cells unexpanded")
        ->default_val(gridList);
    app.add_option("--runs", runs, "Builds per grid (the median is reported)")
        ->check(CLI::Range(1u, 1000u))
        ->default_val(runs);
    app.add_option("--threads", threads,
                   "Threads for the grid builds (default: one per core; Embree keeps its own)")
        ->check(CLI::Range(1u, 1024u));
    app.add_flag("--no-embree", noEmbree, "Leave Embree's build out");
    bool quiet = false;
    app.add_flag("--quiet", quiet, "No progress (each scene's name as it starts) on stderr");
    app.add_option("--json", jsonPath, "Also write every result (all build times) as JSON");
    if (auto status = parseCommandLine("prism-gridbench", app, argc, argv, [&] {
            std::stringstream list(gridList);
            for (std::string g; std::getline(list, g, ',');)
                benchGridOptions(g); // a bad value is a usage error, before any work
        }))
        return *status;
    ParallelThreads threadLimit(threads);
    try {
        std::vector<std::string> grids;
        std::stringstream list(gridList);
        for (std::string g; std::getline(list, g, ',');) {
            benchGridOptions(g); // refuse a bad value before any work
            grids.push_back(g);
        }
        std::vector<Row> rows;
        for (const std::string &path : scenes) {
            std::string name = std::filesystem::path(path).stem().string();
            if (!quiet)
                std::fprintf(stderr, "prism-gridbench: %s\n", name.c_str());
            Scene scene = loadScene(path);
            centerOnCamera(scene);
            if (!noEmbree && embreeAvailable())
                rows.push_back(measureEmbree(scene, name, runs));
            for (const std::string &g : grids)
                rows.push_back(measureGrid(scene, name, g, runs));
        }
        printTable(rows, runs);
        if (!jsonPath.empty()) {
            nlohmann::json all = nlohmann::json::array();
            for (const Row &r : rows)
                all.push_back(toJson(r));
            std::ofstream(jsonPath) << all.dump(2) << "\n";
        }
    } catch (const std::exception &e) {
        std::fprintf(stderr, "prism-gridbench: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
