// The 16 sample offsets of the "seed" mode's bokeh disk ("bokehDisk"): a disk of diameter about 0.9 in units of
// the CoC diameter. Shared by the GPU program (written into its source) and the CPU model.
#pragma once

namespace pfx_dof {

constexpr int kSeedTaps = 16;
constexpr double kSeedDisk[kSeedTaps][2] = {
    {-0.116, -0.433}, {0.116, -0.433}, {0.317, -0.317}, {0.433, -0.116},
    {-0.317, -0.317}, {-0.039, -0.144}, {0.144, -0.039}, {0.433, 0.116},
    {-0.433, -0.116}, {-0.144, 0.039}, {0.039, 0.144}, {0.317, 0.317},
    {-0.433, 0.116}, {-0.317, 0.317}, {-0.116, 0.433}, {0.116, 0.433},
};

}  // namespace pfx_dof
