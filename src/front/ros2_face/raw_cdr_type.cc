#include "ros2_face/raw_cdr_type.h"

#include <dds/dds.h>
#include <dds/ddsi/ddsi_serdata.h>
#include <dds/ddsi/ddsi_sertype.h>
#include <dds/ddsi/q_radmin.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <new>

#include "ros2msg/cdr.h"

namespace sanet::ros2_face {
namespace {

using ros2msg::Bytes;

struct RawType {
  ddsi_sertype c;
};

// The serialized sample, padded to a multiple of 4 (Cyclone may read up to that); `size` is
// the sample's own length, encapsulation header included.
struct RawData {
  ddsi_serdata c;
  Bytes bytes;
  std::size_t size = 0;
};

RawData* Data(ddsi_serdata* d) { return reinterpret_cast<RawData*>(d); }
const RawData* Data(const ddsi_serdata* d) { return reinterpret_cast<const RawData*>(d); }

RawData* NewData(const ddsi_sertype* type, ddsi_serdata_kind kind, std::size_t size) {
  auto* d = new RawData;
  ddsi_serdata_init(&d->c, type, kind);
  d->c.hash = type->serdata_basehash;  // no key: every sample is the one instance
  d->size = size;
  d->bytes.assign((size + 3) / 4 * 4, 0);
  return d;
}

// --- the serdata: one sample's bytes -----------------------------------------------------

bool EqualKeys(const ddsi_serdata*, const ddsi_serdata*) { return true; }
uint32_t SizeOf(const ddsi_serdata* d) { return static_cast<uint32_t>(Data(d)->size); }

// Received over the network: the sample's fragments, in order, possibly overlapping.
ddsi_serdata* FromFragments(const ddsi_sertype* type, ddsi_serdata_kind kind, const nn_rdata* fragchain,
                            std::size_t size) {
  RawData* d = NewData(type, kind, size);
  std::size_t done = 0;
  for (const nn_rdata* f = fragchain; f && done < size; f = f->nextfrag) {
    if (f->maxp1 <= done) continue;
    const auto* payload = NN_RMSG_PAYLOADOFF(f->rmsg, NN_RDATA_PAYLOAD_OFF(f));
    const std::size_t end = std::min<std::size_t>(f->maxp1, size);
    std::memcpy(d->bytes.data() + done, payload + (done - f->min), end - done);
    done = end;
  }
  return &d->c;
}

ddsi_serdata* FromIov(const ddsi_sertype* type, ddsi_serdata_kind kind, ddsrt_msg_iovlen_t niov,
                      const ddsrt_iovec_t* iov, std::size_t size) {
  RawData* d = NewData(type, kind, size);
  std::size_t at = 0;
  for (ddsrt_msg_iovlen_t i = 0; i < niov && at < size; ++i) {
    const std::size_t n = std::min<std::size_t>(iov[i].iov_len, size - at);
    std::memcpy(d->bytes.data() + at, iov[i].iov_base, n);
    at += n;
  }
  return &d->c;
}

ddsi_serdata* FromKeyhash(const ddsi_sertype* type, const ddsi_keyhash*) { return &NewData(type, SDK_KEY, 0)->c; }

ddsi_serdata* FromSample(const ddsi_sertype* type, ddsi_serdata_kind kind, const void* sample) {
  const Bytes& bytes = *static_cast<const Bytes*>(sample);
  RawData* d = NewData(type, kind, kind == SDK_DATA ? bytes.size() : 0);
  if (kind == SDK_DATA) std::copy(bytes.begin(), bytes.end(), d->bytes.begin());
  return &d->c;
}

void ToSer(const ddsi_serdata* d, std::size_t off, std::size_t sz, void* buf) {
  std::memcpy(buf, Data(d)->bytes.data() + off, sz);
}

ddsi_serdata* ToSerRef(const ddsi_serdata* d, std::size_t off, std::size_t sz, ddsrt_iovec_t* ref) {
  ref->iov_base = const_cast<std::uint8_t*>(Data(d)->bytes.data() + off);
  ref->iov_len = static_cast<ddsrt_iov_len_t>(sz);
  return ddsi_serdata_ref(d);
}

void ToSerUnref(ddsi_serdata* d, const ddsrt_iovec_t*) { ddsi_serdata_unref(d); }

bool ToSample(const ddsi_serdata* d, void* sample, void**, void*) {
  const RawData* r = Data(d);
  static_cast<Bytes*>(sample)->assign(r->bytes.begin(), r->bytes.begin() + r->size);
  return true;
}

// Without a key there is nothing to keep but the type.
ddsi_serdata* ToUntyped(const ddsi_serdata* d) { return &NewData(d->type, SDK_KEY, 0)->c; }
bool UntypedToSample(const ddsi_sertype*, const ddsi_serdata*, void*, void**, void*) { return true; }
void FreeData(ddsi_serdata* d) { delete Data(d); }

std::size_t Print(const ddsi_sertype*, const ddsi_serdata* d, char* buf, std::size_t size) {
  return static_cast<std::size_t>(std::snprintf(buf, size, "(%zu bytes of CDR)", Data(d)->size));
}

void Keyhash(const ddsi_serdata*, ddsi_keyhash* buf, bool) { std::memset(buf, 0, sizeof *buf); }

const ddsi_serdata_ops kDataOps = [] {
  ddsi_serdata_ops ops{};
  ops.eqkey = EqualKeys;
  ops.get_size = SizeOf;
  ops.from_ser = FromFragments;
  ops.from_ser_iov = FromIov;
  ops.from_keyhash = FromKeyhash;
  ops.from_sample = FromSample;
  ops.to_ser = ToSer;
  ops.to_ser_ref = ToSerRef;
  ops.to_ser_unref = ToSerUnref;
  ops.to_sample = ToSample;
  ops.to_untyped = ToUntyped;
  ops.untyped_to_sample = UntypedToSample;
  ops.free = FreeData;
  ops.print = Print;
  ops.get_keyhash = Keyhash;
  return ops;
}();

// --- the sertype: samples are Bytes -------------------------------------------------------

void FreeType(ddsi_sertype* t) {
  ddsi_sertype_fini(t);
  delete reinterpret_cast<RawType*>(t);
}

void ZeroSamples(const ddsi_sertype*, void* samples, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) static_cast<Bytes*>(samples)[i].clear();
}

void ReallocSamples(void** ptrs, const ddsi_sertype*, void* old, std::size_t oldcount, std::size_t count) {
  auto* grown = new Bytes[count];
  for (std::size_t i = 0; i < std::min(oldcount, count); ++i) grown[i] = std::move(static_cast<Bytes*>(old)[i]);
  delete[] static_cast<Bytes*>(old);
  for (std::size_t i = 0; i < count; ++i) ptrs[i] = &grown[i];
}

void FreeSamples(const ddsi_sertype*, void** ptrs, std::size_t count, dds_free_op_t op) {
  if (count == 0) return;
  if (op & DDS_FREE_ALL_BIT) {
    delete[] static_cast<Bytes*>(ptrs[0]);
    return;
  }
  for (std::size_t i = 0; i < count; ++i) static_cast<Bytes*>(ptrs[i])->clear();
}

bool EqualTypes(const ddsi_sertype*, const ddsi_sertype*) { return true; }  // the name says it all
uint32_t HashType(const ddsi_sertype*) { return 0; }
std::size_t SerializedSize(const ddsi_sertype*, const void* sample) {
  return static_cast<const Bytes*>(sample)->size();
}

bool SerializeInto(const ddsi_sertype*, const void* sample, void* buffer, std::size_t size) {
  const Bytes& bytes = *static_cast<const Bytes*>(sample);
  if (size < bytes.size()) return false;
  std::memcpy(buffer, bytes.data(), bytes.size());
  return true;
}

const ddsi_sertype_ops kTypeOps = [] {
  ddsi_sertype_ops ops{};
  ops.version = ddsi_sertype_v0;
  ops.free = FreeType;
  ops.zero_samples = ZeroSamples;
  ops.realloc_samples = ReallocSamples;
  ops.free_samples = FreeSamples;
  ops.equal = EqualTypes;
  ops.hash = HashType;
  ops.get_serialized_size = SerializedSize;
  ops.serialize_into = SerializeInto;
  return ops;
}();

}  // namespace

ddsi_sertype* MakeRawCdrType(const std::string& dds_type_name) {
  auto* t = new RawType{};
  ddsi_sertype_init_flags(&t->c, dds_type_name.c_str(), &kTypeOps, &kDataOps, DDSI_SERTYPE_FLAG_TOPICKIND_NO_KEY);
  return &t->c;
}

}  // namespace sanet::ros2_face
