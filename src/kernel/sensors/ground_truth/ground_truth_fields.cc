// Ground truth's keys in a scenario.
#include "scenario/sensor_fields.h"
#include "sensors/ground_truth/ground_truth.h"

namespace sanet::scenario {
namespace {

using sensors::GroundTruthSettings;

const Fields<GroundTruthSettings>& GroundTruthFields() {
  static const Fields<GroundTruthSettings> fields = [] {
    Fields<GroundTruthSettings> f;
    f.Number("noise_position", Member(&GroundTruthSettings::noise_position), "m", 0, 1000,
             "standard deviation added to x and y");
    f.Number("noise_angle", Member(&GroundTruthSettings::noise_angle), "rad", 0, 10,
             "standard deviation added to theta");
    return f;
  }();
  return fields;
}

}  // namespace

const SensorFields& GroundTruthSensorFields() {
  static const DeclaredKeys<GroundTruthSettings> keys(GroundTruthFields());
  return keys;
}

}  // namespace sanet::scenario
