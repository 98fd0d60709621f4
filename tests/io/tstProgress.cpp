/// \file tstProgress.cpp
/// \brief The progress line of long loops (drivers/log/Progress.hpp).

#include "drivers/log/Progress.hpp"

#include <gtest/gtest.h>

namespace {

using hikiln::log::Progress;

TEST(Progress, line_gives_time_share_rate_and_eta) {
  EXPECT_EQ(Progress::format(1.5, 6.0, 2500.0, 90.0),
            "t = 1.500 / 6.000 s ( 25.0 %), 2.5e+03 steps/s, ETA 1m30s");
}

TEST(Progress, past_the_end_has_no_eta_and_carries_the_note) {
  // a settle past its minimum duration: the ETA is unknown, the note says what the loop waits for
  EXPECT_EQ(Progress::format(0.4, 0.2, 1190.0, -1.0, "waiting for rest"),
            "t = 0.400 / 0.200 s (200.0 %), 1.19e+03 steps/s, ETA --, waiting for rest");
}

} // namespace
