// Splitting the frames between pairs into contacts (trace/radio_contacts.h): the silence that
// ends a contact, both directions, pairs kept apart, contacts open at the run's end, and the
// inter-contact times.
#include "trace/radio_contacts.h"

#include <gtest/gtest.h>

namespace sanet::trace {
namespace {

TEST(RadioContacts, AGapOfExactlyTheSilenceKeepsTheContactAndALongerOneEndsIt) {
  RadioContacts contacts(2.0);
  contacts.Heard(1.0, 0, 1);
  contacts.Heard(3.0, 0, 1);         // 2 s later: the same contact
  contacts.Heard(5.0 + 1e-9, 0, 1);  // just over 2 s: a new one
  const auto all = contacts.Contacts(100);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_DOUBLE_EQ(all[0].start, 1.0);
  EXPECT_DOUBLE_EQ(all[0].end, 3.0);
  EXPECT_EQ(all[0].frames(), 2u);
  EXPECT_DOUBLE_EQ(all[1].start, 5.0 + 1e-9);
  EXPECT_DOUBLE_EQ(all[1].duration(), 0.0) << "a contact of one frame lasts 0 s";
  EXPECT_FALSE(all[0].open);
  EXPECT_FALSE(all[1].open);
}

TEST(RadioContacts, FramesEitherWayAreOneContactOfTheUnorderedPair) {
  RadioContacts contacts(1.0);
  contacts.Heard(10.0, 3, 1);  // node 1 heard node 3
  contacts.Heard(10.5, 1, 3);
  contacts.Heard(11.0, 3, 1);
  const auto all = contacts.Contacts(50);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].a, 1u);
  EXPECT_EQ(all[0].b, 3u);
  EXPECT_EQ(all[0].a_to_b, 1u) << "node 3 heard node 1 once";
  EXPECT_EQ(all[0].b_to_a, 2u);
  EXPECT_DOUBLE_EQ(all[0].start, 10.0);
  EXPECT_DOUBLE_EQ(all[0].end, 11.0);
}

TEST(RadioContacts, PairsAreApartAndContactsComeByStartTime) {
  RadioContacts contacts(1.0);
  contacts.Heard(0.0, 0, 1);
  contacts.Heard(0.5, 0, 2);
  contacts.Heard(0.9, 0, 1);
  contacts.Heard(1.8, 0, 1);  // 0.9 s after 0-1's last frame: still its first contact
  contacts.Heard(3.0, 2, 0);  // 2.5 s after 0-2's: a second contact of that pair
  const auto all = contacts.Contacts(10);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(std::make_pair(all[0].a, all[0].b), std::make_pair(0u, 1u));
  EXPECT_EQ(all[0].frames(), 3u);
  EXPECT_EQ(std::make_pair(all[1].a, all[1].b), std::make_pair(0u, 2u));
  EXPECT_DOUBLE_EQ(all[2].start, 3.0);
  EXPECT_EQ(all[2].b_to_a, 1u);
}

TEST(RadioContacts, AContactWithinTheSilenceOfTheRunsEndIsOpen) {
  RadioContacts contacts(2.0);
  contacts.Heard(1.0, 0, 1);
  contacts.Heard(8.0, 1, 2);
  const auto all = contacts.Contacts(10.0);  // 9 s after 0-1's frame, exactly 2 s after 1-2's
  ASSERT_EQ(all.size(), 2u);
  EXPECT_FALSE(all[0].open);
  EXPECT_TRUE(all[1].open) << "a frame at the run's end would still have joined it";
  EXPECT_FALSE(contacts.Contacts(10.0 + 1e-9)[1].open);
}

TEST(RadioContacts, InterContactTimesGoFromOneContactsEndToTheNextOnesStartOfTheSamePair) {
  RadioContacts contacts(1.0);
  for (double t : {0.0, 0.5, 5.0, 5.5, 6.0, 20.0}) contacts.Heard(t, 0, 1);
  contacts.Heard(2.0, 1, 2);
  contacts.Heard(4.0, 2, 1);
  const auto all = contacts.Contacts(20.0);
  ASSERT_EQ(all.size(), 5u);
  EXPECT_TRUE(all.back().open);
  const std::vector<double> gaps = InterContactTimes(all);
  ASSERT_EQ(gaps.size(), 3u);
  EXPECT_DOUBLE_EQ(gaps[0], 2.0);   // 1-2: 2 to 4
  EXPECT_DOUBLE_EQ(gaps[1], 4.5);   // 0-1: 0.5 to 5
  EXPECT_DOUBLE_EQ(gaps[2], 14.0);  // 0-1: 6 to 20, the open contact's start is known
}

TEST(RadioContacts, ANodeHearingItselfIsNoContact) {
  RadioContacts contacts(1.0);
  contacts.Heard(1.0, 4, 4);
  EXPECT_TRUE(contacts.Contacts(2.0).empty());
}

}  // namespace
}  // namespace sanet::trace
