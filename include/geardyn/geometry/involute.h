#pragma once
/// \file
/// The involute function and its inverse, the two primitives of involute gear geometry.

namespace geardyn {

/// inv(α) = tan α − α, the involute function [rad]; α in [0, π/2) [rad].
double involute(double alpha);

/// The pressure angle α [rad] with inv(α) = value, for value ≥ 0 [rad]. Newton's method from the
/// series start α ≈ (3 v)^(1/3); converges to machine precision in a few steps.
/// Throws InputError for a negative or non-finite value.
double inverseInvolute(double value);

}  // namespace geardyn
