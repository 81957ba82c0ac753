#include "core/RootTask.hpp"

#include <exception>
#include <string>

#include <Teuchos_CommHelpers.hpp>

#include "signorini/core/Error.hpp"

namespace signorini::detail {

void runOnRoot(const Comm& comm, const std::function<void()>& task) {
  enum : int { kNone = 0, kInput = 1, kOther = 2 };
  int status[2] = {kNone, 0};  // kind, message length
  std::string message;
  if (comm.getRank() == 0) {
    try {
      task();
    } catch (const InputError& e) {
      status[0] = kInput;
      message = e.what();
    } catch (const std::exception& e) {
      status[0] = kOther;
      message = e.what();
    }
    status[1] = static_cast<int>(message.size());
  }
  Teuchos::broadcast(comm, 0, 2, status);
  if (status[0] == kNone) return;
  message.resize(status[1]);
  if (status[1] > 0) Teuchos::broadcast(comm, 0, status[1], &message[0]);
  if (status[0] == kInput) throw InputError(message);
  throw Error(message);
}

}  // namespace signorini::detail
