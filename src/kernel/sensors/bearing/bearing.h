// Range and bearing to other nodes, as a beacon or a camera with known landmarks gives them.
#pragma once

namespace sanet::sensors {

struct BearingSettings {
  double range = 0;           // m; beyond it the sensor answers nothing
  double noise_distance = 0;  // m, standard deviation
  double noise_angle = 0;     // rad, standard deviation
};

}  // namespace sanet::sensors
