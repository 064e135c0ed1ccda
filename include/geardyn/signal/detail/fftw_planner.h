#pragma once
/// \file
/// FFTW's planner is not thread-safe (only the execution of a plan is): every plan of the
/// library is made and destroyed under this one lock, so that analyses may run on several
/// threads (noise studies, sweeps). Internal.

#include <mutex>

namespace geardyn::detail {

std::mutex& fftwPlannerMutex();

}  // namespace geardyn::detail
