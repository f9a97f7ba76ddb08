#include "study/mpi_link.h"

#include <mpi.h>

#include <chrono>
#include <climits>
#include <stdexcept>
#include <thread>

namespace sanet::study {

struct MpiLink::Outgoing {
  std::string bytes;
  MPI_Request request = MPI_REQUEST_NULL;
};

MpiSession& MpiSession::Get() {
  static MpiSession session;
  return session;
}

MpiSession::MpiSession() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SINGLE, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

MpiLink::MpiLink() = default;

MpiLink::~MpiLink() {
  // Sends a rank that is gone will never take: their buffers stay allocated, as MPI may still
  // read them until it finishes.
  if (!Flush(10)) new std::list<Outgoing>(std::move(outgoing_));
}

void MpiLink::Send(int to, int tag, std::string bytes) {
  if (bytes.size() > static_cast<std::size_t>(INT_MAX))
    throw std::length_error("a message of " + std::to_string(bytes.size()) + " bytes is over MPI's 2 GiB");
  Outgoing& out = outgoing_.emplace_back();
  out.bytes = std::move(bytes);
  MPI_Isend(out.bytes.data(), static_cast<int>(out.bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD, &out.request);
  Progress();
}

std::optional<MpiMessage> MpiLink::TryReceive(int from, int tag) {
  int waiting = 0;
  MPI_Status status;
  MPI_Iprobe(from, tag, MPI_COMM_WORLD, &waiting, &status);
  if (!waiting) return std::nullopt;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  MpiMessage message{status.MPI_SOURCE, status.MPI_TAG, std::string(static_cast<std::size_t>(count), '\0')};
  MPI_Request request;
  MPI_Irecv(message.bytes.data(), count, MPI_BYTE, message.from, message.tag, MPI_COMM_WORLD, &request);
  // The sender may need to take part (a large message comes in pieces): poll, and let our own
  // sends go meanwhile, so that two ranks receiving from each other both get theirs.
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return message;
    Progress();
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

bool MpiLink::Progress() {
  for (auto it = outgoing_.begin(); it != outgoing_.end();) {
    int done = 0;
    MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
    it = done ? outgoing_.erase(it) : std::next(it);
  }
  return outgoing_.empty();
}

bool MpiLink::Flush(double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!Progress()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    PollPause();
  }
  return true;
}

void PollPause() { std::this_thread::sleep_for(std::chrono::milliseconds(10)); }

}  // namespace sanet::study
