#pragma once
/// \file
/// Constant-force pauses under spring control (`[load] force_pauses`): the AFM "creep" (dwell) segment, where the
/// instrument's feedback moves the base so that the spring's force stays at its value at the pause's start.

namespace mdr::drivers {

/// One pause [start, end] [s] of a spring-controlled history. During it the force is held at its value at `start`
/// (force control: the depth creeps, eq. 19 solved on the foundation as under control = "force") and the base
/// follows as z = d + F / k. After it the base history resumes with its own slopes from the z reached: every later
/// history value is shifted by z(end) - z_history(end), so that z is continuous. The history's values inside the
/// pause are not used.
struct ForcePause {
    double start = 0.0;  ///< t_start [s]: the force held is the one reached here (it must be > 0: a contact)
    double end = 0.0;    ///< t_end [s] > t_start
};

}  // namespace mdr::drivers
