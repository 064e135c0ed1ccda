#pragma once
/// \file
/// Simulated probe records of `geardyn train`'s `time` analysis ([probes],
/// train_probes_analysis.cpp), called by runTime: x/y at named stations of any train and a
/// keyphasor, in the CSV/WAV/HDF5 forms `geardyn spectrum` reads, with the frequency-domain
/// steady state's forward/backward whirl at the mesh orders beside them.

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// A probe station: the body whose (y, z) translation the probe reads, and the sign of its
/// shaft's rotation about the train's x axis at the input speed (+1 or −1).
struct ProbeStation {
  std::string name;  ///< as given in probes.stations
  int body = 0;
  double rotation_sign = 1.0;
};

/// The stations of probes.stations at input speed `speed` [rad/s] (InputError naming the key, the
/// value and the known shafts and bearings, with a did-you-mean, for an unknown name; a torsional
/// train has no probes; a body in a rotating carrier frame is refused).
std::vector<ProbeStation> probeStations(const GearTrainModel& model, const config::Config& analysis,
                                        double speed);

/// Checks [probes] before the time run (stations, keyphasor shaft, sample rate against twice the
/// highest tracked frequency, an integer rate for WAV) so that bad input fails before Newmark.
void checkTrainProbes(const GearTrainModel& model, const config::Config& analysis, double speed);

/// Samples the steady-state window of `r` (recorded with TrainTimeOptions::record_rates) at the
/// probe rate (cubic Hermite between Newmark steps), adds the keyphasor and the noise, and
/// queues probes.csv/.wav/.h5; summary.results["probes"] holds the record's description and,
/// when `steady` is given, the forward/backward whirl of every station at every tracked mesh
/// order from the frequency-domain steady state (the values `spectrum` should find).
void writeTrainProbes(const GearTrainModel& model, const config::Config& analysis, double speed,
                      const TrainTimeResponse& r, const TrainSteadyState* steady,
                      AnalysisResult& result, std::string& text);

}  // namespace geardyn::analysis::detail
