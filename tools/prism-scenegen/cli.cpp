#include "cli.h"

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "command_line.h"
#include "core/error.h"
#include "generators.h"
#include "scene_text.h"

namespace prism::scenegen {
namespace {

// A path as the scene format takes it: bare, or quoted when it holds spaces.
std::string scenePathToken(const std::string &path, const char *what) {
    if (path.empty() || path.find_first_of("\"#\r\n") != std::string::npos)
        throw Error(std::string(what) + " '" + path + "' cannot be written into a scene file");
    return path.find_first_of(" \t") == std::string::npos ? path : "\"" + path + "\"";
}

uint64_t parseSeed(const std::string &text) {
    uint64_t seed = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed);
    if (text.empty() || error != std::errc() || end != text.data() + text.size())
        throw Error("--seed must be a whole number from 0 to 18446744073709551615, got '" + text +
                    "'");
    return seed;
}

} // namespace

int runScenegen(int argc, char **argv) {
    CLI::App app{"prism-scenegen: writes Prism's generated benchmark scenes (.scene, format v1). "
                 "The same arguments give the same bytes on every machine."};
    app.set_version_flag("--version", "prism-scenegen 0.1.0");
    app.require_subcommand(1);

    std::string output;
    auto addOutput = [&](CLI::App *sub) {
        sub->add_option("-o,--output", output, "Scene file to write (replaced atomically)")
            ->required();
    };

    RandomOptions random;
    CLI::App *randomCmd = app.add_subcommand(
        "random", "N spheres of random position, radius, colour and material in a box on a "
                  "floor, against two walls (the original's rand50/rand500/rand5000)");
    randomCmd->add_option("--count", random.count, "Number of spheres")
        ->check(CLI::Range(1u, 1'000'000u))
        ->default_val(random.count);
    // Read as text: CLI11 wraps -1 round and saturates overflow instead of refusing them.
    std::string seedText = std::to_string(random.seed);
    randomCmd->add_option("--seed", seedText, "Seed of the PCG32 random stream, 0 .. 2^64-1")
        ->default_val(seedText);
    randomCmd->add_option("--box", random.box, "Side of the cube that holds the spheres")
        ->check(CLI::PositiveNumber)
        ->default_val(random.box);
    randomCmd->add_option("--min-radius", random.minRadius, "Smallest sphere radius")
        ->check(CLI::PositiveNumber)
        ->default_val(random.minRadius);
    randomCmd->add_option("--max-radius", random.maxRadius, "Largest sphere radius")
        ->check(CLI::PositiveNumber)
        ->default_val(random.maxRadius);
    randomCmd
        ->add_option("--materials", random.materials,
                     "Size of the random material palette the spheres draw from")
        ->check(CLI::Range(1u, 1000u))
        ->default_val(random.materials);
    addOutput(randomCmd);

    LatticeOptions lattice;
    CLI::App *latticeCmd = app.add_subcommand(
        "lattice", "A regular N x N x N lattice of spheres above a floor (the original's grid)");
    latticeCmd->add_option("--size", lattice.size, "Spheres per side")
        ->check(CLI::Range(1u, 100u))
        ->default_val(lattice.size);
    latticeCmd->add_option("--spacing", lattice.spacing, "Distance between neighbouring centres")
        ->check(CLI::PositiveNumber)
        ->default_val(lattice.spacing);
    latticeCmd->add_option("--radius", lattice.radius, "Sphere radius (at most spacing / 2)")
        ->check(CLI::PositiveNumber)
        ->default_val(lattice.radius);
    addOutput(latticeCmd);

    ToriOptions tori;
    CLI::App *toriCmd =
        app.add_subcommand("tori", "A row of tessellated tori on a floor, any number of triangles: "
                                   "per-ray cost against triangle count");
    toriCmd
        ->add_option("--triangles", tori.triangles, "Triangles in all, about (18 x count .. 2e7)")
        ->default_val(tori.triangles);
    toriCmd->add_option("--count", tori.count, "Number of tori (1..100)")->default_val(tori.count);
    toriCmd
        ->add_option("--shards", tori.shards,
                     "Long, thin triangles through the whole row (0..64): a few huge triangles "
                     "among many tiny ones")
        ->default_val(tori.shards);
    addOutput(toriCmd);

    SphereMeshOptions sphereMesh;
    CLI::App *sphereMeshCmd = app.add_subcommand(
        "sphere-mesh", "One dense closed mesh (a finely tessellated sphere) over a floor, "
                       "written as OBJ beside the scene (FILE.obj for FILE.scene)");
    sphereMeshCmd->add_option("--triangles", sphereMesh.triangles, "Triangles, about (12 .. 2e7)")
        ->default_val(sphereMesh.triangles);
    sphereMeshCmd->add_flag("--smooth", sphereMesh.smooth,
                            "Smooth-shade the mesh (vertex normals made when the scene loads)");
    addOutput(sphereMeshCmd);

    CLI::App *mixedCmd = app.add_subcommand(
        "mixed", "Planes, spheres and triangle solids, 621 primitives (the original's scene)");
    addOutput(mixedCmd);

    std::string bunnyPath = "../models/bunny/bunny_lowres.obj";
    CLI::App *objectsCmd = app.add_subcommand(
        "objects", "The bunny and other triangle objects, 5436 triangles (the original's objects)");
    objectsCmd
        ->add_option("--bunny", bunnyPath,
                     "Bunny OBJ path as written in the scene (relative to the scene file)")
        ->default_val(bunnyPath);
    addOutput(objectsCmd);

    if (auto status = parseCommandLine("prism-scenegen", app, argc, argv))
        return *status;

    std::string text;
    if (randomCmd->parsed()) {
        random.seed = parseSeed(seedText);
        text = randomScene(random, randomCommand(random));
    } else if (latticeCmd->parsed())
        text = latticeScene(lattice, latticeCommand(lattice));
    else if (toriCmd->parsed())
        text = toriScene(tori, toriCommand(tori));
    else if (sphereMeshCmd->parsed()) {
        // The OBJ first, so that a scene never names a mesh that is not there.
        std::filesystem::path objPath = std::filesystem::path(output).replace_extension(".obj");
        std::string command = sphereMeshCommand(sphereMesh);
        text = sphereMeshScene(
            sphereMesh, scenePathToken(objPath.filename().string(), "mesh file name"), command);
        writeFileAtomically(objPath, sphereMeshObj(sphereMesh, command));
    } else if (mixedCmd->parsed())
        text = mixedScene("prism-scenegen mixed");
    else {
        std::string token = scenePathToken(bunnyPath, "--bunny path");
        std::string command = "prism-scenegen objects";
        if (bunnyPath != "../models/bunny/bunny_lowres.obj")
            command += " --bunny '" + bunnyPath + "'";
        text = objectsScene(token, command);
    }
    writeFileAtomically(output, text);
    return 0;
}

} // namespace prism::scenegen
