#include "core/RootTask.hpp"

#include <chrono>
#include <exception>
#include <string>
#include <thread>

#include <mpi.h>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include "signorini/core/Error.hpp"

namespace signorini::detail {

namespace {

enum : int { kNone = 0, kInput = 1, kOther = 2 };

// Runs the task, returning the kind of error it threw (kNone: none) and its message.
int run(const std::function<void()>& task, std::string& message) {
  try {
    task();
  } catch (const InputError& e) {
    message = e.what();
    return kInput;
  } catch (const std::exception& e) {
    message = e.what();
    return kOther;
  }
  return kNone;
}

// Returns once every rank called it, the waiting ones asleep rather than polling in MPI: where
// ranks share cores (more ranks than cores, hyperthreads), a polling rank would take the
// core that rank 0's serial task needs.
void waitAsleep(const Comm& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  if (mpi == nullptr || comm.getSize() == 1) return;
  MPI_Request request;
  MPI_Ibarrier(*mpi->getRawMpiComm(), &request);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

// Throws on every rank the error of rank `from` (kind and message as `status` there).
void throwFrom(const Comm& comm, int from, int status[2], std::string& message) {
  Teuchos::broadcast(comm, from, 2, status);
  if (status[0] == kNone) return;
  message.resize(status[1]);
  if (status[1] > 0) Teuchos::broadcast(comm, from, status[1], &message[0]);
  if (status[0] == kInput) throw InputError(message);
  throw Error(message);
}

}  // namespace

void runOnRoot(const Comm& comm, const std::function<void()>& task) {
  int status[2] = {kNone, 0};  // kind, message length
  std::string message;
  if (comm.getRank() == 0) {
    status[0] = run(task, message);
    status[1] = static_cast<int>(message.size());
  }
  waitAsleep(comm);
  throwFrom(comm, 0, status, message);
}

void runOnEveryRank(const Comm& comm, const std::function<void()>& task) {
  std::string message;
  int status[2] = {run(task, message), 0};
  status[1] = static_cast<int>(message.size());
  const int failed = status[0] == kNone ? comm.getSize() : comm.getRank();
  int first = failed;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &failed, &first);
  if (first < comm.getSize()) throwFrom(comm, first, status, message);
}

}  // namespace signorini::detail
