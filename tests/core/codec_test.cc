#include "sanet/codec.h"

#include <gtest/gtest.h>

namespace sanet {
namespace {

TEST(Codec, FieldsComeBackInOrder) {
  const Bytes b = Writer().U8(7).Bool(true).Bool(false).U32(123456).I32(-5).F64(-2.5).Text("mote3").bytes();
  Reader r(b);
  EXPECT_EQ(r.U8(), 7);
  EXPECT_TRUE(r.Bool());
  EXPECT_FALSE(r.Bool());
  EXPECT_EQ(r.U32(), 123456u);
  EXPECT_EQ(r.I32(), -5);
  EXPECT_DOUBLE_EQ(r.F64(), -2.5);
  EXPECT_EQ(r.Text(), "mote3");
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.at_end());
}

TEST(Codec, BytesAreLittleEndianWhateverTheMachine) {
  EXPECT_EQ(Writer().U32(0x01020304).bytes(), (Bytes{4, 3, 2, 1}));
}

TEST(Codec, ReadingPastTheEndIsReportedNotUndefined) {
  const Bytes b = Writer().U8(1).bytes();
  Reader r(b);
  r.U8();
  EXPECT_EQ(r.U32(), 0u);
  EXPECT_FALSE(r.ok());
  Reader t(Writer().U32(1000).bytes());  // a text claiming 1000 bytes that are not there
  EXPECT_EQ(t.Text(), "");
  EXPECT_FALSE(t.ok());
}

}  // namespace
}  // namespace sanet
