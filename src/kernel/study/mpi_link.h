// Messages between MPI ranks that never wait inside MPI: Open MPI's blocking calls poll at full
// CPU, and two ranks each blocked sending the other a message too large to be buffered (above the
// eager limit, 4 KiB over shared memory) wait for each other forever. Here every send is
// non-blocking and kept until MPI says it is done; a message is received only once it is known
// to be waiting; and whoever waits sleeps between polls.
#pragma once

#include <list>
#include <optional>
#include <string>

namespace sanet::study {

// MPI is started the first time it is needed and finished when the program ends.
class MpiSession {
 public:
  static MpiSession& Get();
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  MpiSession();
  ~MpiSession();
  int rank_ = 0, size_ = 1;
};

struct MpiMessage {
  int from = 0;
  int tag = 0;
  std::string bytes;
};

class MpiLink {
 public:
  MpiLink();
  ~MpiLink();
  // Starts sending; the bytes are kept until the send completes.
  void Send(int to, int tag, std::string bytes);
  // The next message from `from` (or any rank) with `tag` (or any tag), if one is waiting.
  std::optional<MpiMessage> TryReceive(int from, int tag);
  // Lets finished sends go; true when none is left.
  bool Progress();
  // Waits (polling, sleeping between polls) until every send is done or `seconds` have passed;
  // false if some are left (a rank that is gone never takes them).
  bool Flush(double seconds);

 private:
  struct Outgoing;
  std::list<Outgoing> outgoing_;
};

// Sleeps between polls of a rank that waits: long enough to cost almost no CPU, short enough
// that a run's end is noticed at once next to its length.
void PollPause();

}  // namespace sanet::study
