#include "core/problem/CollectiveError.hpp"

#include "base/InputError.hpp"

#include <Teuchos_CommHelpers.hpp>

namespace contactlab {

void agreeOnError(const Comm& comm, const std::string& localMessage) {
  const int size = comm.getSize();
  int local = localMessage.empty() ? size : comm.getRank(), first = size;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &local, &first);
  if (first == size) return;
  int length = static_cast<int>(localMessage.size());
  Teuchos::broadcast(comm, first, 1, &length);
  std::string message = localMessage;
  message.resize(length);
  Teuchos::broadcast(comm, first, length, message.data());
  throw InputError(message);
}

}  // namespace contactlab
