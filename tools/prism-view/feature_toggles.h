#pragma once
// The tracer features a user switches in the overlay and a soak run switches by script: each
// change rebuilds the tracer with other specialization constants (or a one-cell grid).
namespace prism {

// The original system's feature-cost experiment.
struct FeatureToggles {
    bool shadows = true;
    bool reflection = true;
    bool refraction = true;
    bool grid = true; // off: one cell, every ray tests every primitive
    bool operator==(const FeatureToggles &) const = default;
};

} // namespace prism
