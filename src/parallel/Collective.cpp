#include "parallel/Collective.hpp"

#include <stdexcept>
#include <string>

#include "core/InputError.hpp"
#include "core/Material.hpp"

namespace pf {
namespace {

// The error as text: its kind in the first character, so the other ranks can throw the same type.
std::string encode(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const InputError& e) {
    return std::string("I") + e.what();
  } catch (const ConstitutiveFailure& e) {
    return std::string("C") + e.what();
  } catch (const std::exception& e) {
    return std::string("R") + e.what();
  } catch (...) {
    return "Runknown exception";
  }
}

[[noreturn]] void throwDecoded(const std::string& text) {
  const std::string what = text.substr(1);
  if (text[0] == 'I') throw InputError(what);
  if (text[0] == 'C') throw ConstitutiveFailure(what);
  throw std::runtime_error(what);
}

}  // namespace

void agreeOnFailure(const Communicator& comm, const std::exception_ptr& error) {
  const int first = comm.firstFailing(static_cast<bool>(error));
  if (first < 0) return;
  const std::string text = comm.broadcast(comm.rank() == first ? encode(error) : std::string(), first);
  // The failing rank rethrows its own exception (its exact type); the others throw its copy.
  if (comm.rank() == first) std::rethrow_exception(error);
  throwDecoded(text);
}

}  // namespace pf
