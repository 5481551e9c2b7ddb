#include "parallel/mpi_context.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <iostream>
#include <list>
#include <thread>

#ifdef __linux__
#include <sched.h>
#include <sys/prctl.h>
#endif

namespace cambrian {

namespace {

// throws Error(mpi) when an MPI call did not succeed
void check(int code, const char* call, int rank) {
  if (code == MPI_SUCCESS)
    return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw Error(ExitCode::mpi, std::string("rank ") + std::to_string(rank) + ": " + call +
                                 " failed: " + std::string(text, static_cast<std::size_t>(length)));
}

// receives a message from `source` with `tag` (either may be a wildcard) into `out` when one is
// waiting: probe without blocking, then receive exactly what is there; false when none is
bool receiveWaiting(MPI_Comm comm, int source, int tag, int rank, Message& out) {
  int flag = 0;
  MPI_Status status;
  check(MPI_Iprobe(source, tag, comm, &flag, &status), "MPI_Iprobe", rank);
  if (!flag)
    return false;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  out.bytes.resize(static_cast<std::size_t>(count));
  check(MPI_Recv(out.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, comm,
                 MPI_STATUS_IGNORE),
        "MPI_Recv", rank);
  out.source = status.MPI_SOURCE;
  out.tag = static_cast<Tag>(status.MPI_TAG);
  return true;
}

constexpr int kProbesBeforeSleeping = 4;

// waits until tryOnce(message) receives one: probe and sleep, since Open MPI's blocking
// receive would spin a core
template <class Try>
Message waitFor(Try tryOnce, long longest_sleep_micros, long urgent_micros) {
  Message message;
  // a message already on its way often needs a probe or two to be matched: no sleep for those
  for (int attempt = 0; attempt < kProbesBeforeSleeping; ++attempt) {
    if (tryOnce(message))
      return message;
  }
  // short sleeps while the message is likely to come soon, then longer ones
  Backoff backoff;
  const long first =
      urgent_micros > 0 ? std::min(urgent_micros, longest_sleep_micros) : longest_sleep_micros;
  backoff.range(std::min(Backoff::kMin, first), first);
  auto start = std::chrono::steady_clock::now();
  bool patient = first == longest_sleep_micros;
  while (!tryOnce(message)) {
    backoff.wait();
    if (!patient && std::chrono::steady_clock::now() - start >
                        std::chrono::microseconds(MpiContext::kUrgentForMicros)) {
      backoff.range(first, longest_sleep_micros);
      patient = true;
    }
  }
  return message;
}

}  // namespace

// the communicator a context speaks over: the world, or one of split()'s (freed with it)
struct MpiContext::Communicator {
  MPI_Comm comm = MPI_COMM_WORLD;
  ~Communicator() {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (comm != MPI_COMM_WORLD && comm != MPI_COMM_NULL && !finalised)
      MPI_Comm_free(&comm);
  }
};

// sends under way: each request beside the bytes it reads from (a list, so they never move)
struct MpiContext::PostedSends {
  struct Send {
    MPI_Request request = MPI_REQUEST_NULL;
    std::vector<std::uint8_t> bytes;
  };
  std::list<Send> sends;
};

bool keepCoreWhenIdle(int local_ranks, int cores) {
  return local_ranks > 0 && cores > 0 && local_ranks <= cores + 1;
}

int usableCores() {
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0)
    return CPU_COUNT(&set);
#endif
  return static_cast<int>(std::thread::hardware_concurrency());
}

MpiContext::MpiContext(int* argc, char*** argv)
    : communicator_(std::make_unique<Communicator>()), posted_(std::make_unique<PostedSends>()) {
  // initialise unless someone already did
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    // Open MPI's yield when idle off where every worker has a core (keepCoreWhenIdle); a value
    // set with --mca or in the environment stays
    if (const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
        local && keepCoreWhenIdle(std::atoi(local), usableCores()))
      setenv("OMPI_MCA_mpi_yield_when_idle", "0", 0);
    if (MPI_Init(argc, argv) != MPI_SUCCESS)
      throw Error(ExitCode::mpi, "MPI_Init failed");
    owns_ = true;
  }
  // errors come back as codes, so they become exceptions and then MPI_Abort, never a hang
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
#ifdef __linux__
  // sleeps of 50 us should not become 100 us (the default slack is 50 us)
  prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
#endif
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiContext::MpiContext(std::unique_ptr<Communicator> communicator)
    : communicator_(std::move(communicator)), posted_(std::make_unique<PostedSends>()) {
  MPI_Comm_set_errhandler(communicator_->comm, MPI_ERRORS_RETURN);
  MPI_Comm_rank(communicator_->comm, &rank_);
  MPI_Comm_size(communicator_->comm, &size_);
}

std::unique_ptr<MpiContext> MpiContext::split(int color) const {
  auto communicator = std::make_unique<Communicator>();
  check(MPI_Comm_split(communicator_->comm, color < 0 ? MPI_UNDEFINED : color, rank_,
                       &communicator->comm),
        "MPI_Comm_split", rank_);
  if (communicator->comm == MPI_COMM_NULL)
    return nullptr;
  return std::unique_ptr<MpiContext>(new MpiContext(std::move(communicator)));
}

MpiContext::~MpiContext() {
  // sends still under way are abandoned: MPI_Finalize or MPI_Abort follows
  for (auto& send : posted_->sends) {
    if (send.request != MPI_REQUEST_NULL)
      MPI_Request_free(&send.request);
  }
  communicator_.reset();
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (owns_ && !finalised)
    MPI_Finalize();
}

int MpiContext::yieldWhenIdle() const {
  // the control variable, through the tool interface (readable after MPI_Init)
  int provided = 0;
  if (MPI_T_init_thread(MPI_THREAD_SINGLE, &provided) != MPI_SUCCESS)
    return -1;
  int value = -1, count = 0;
  MPI_T_cvar_get_num(&count);
  for (int index = 0; index < count && value < 0; ++index) {
    char name[256], about[1024];
    int name_length = sizeof name, about_length = sizeof about, verbosity = 0, bind = 0, scope = 0;
    MPI_Datatype type;
    MPI_T_enum enumeration;
    if (MPI_T_cvar_get_info(index, name, &name_length, &verbosity, &type, &enumeration, about,
                            &about_length, &bind, &scope) != MPI_SUCCESS ||
        std::strcmp(name, "mpi_yield_when_idle") != 0 || (type != MPI_C_BOOL && type != MPI_INT))
      continue;
    MPI_T_cvar_handle handle;
    int elements = 0;
    if (MPI_T_cvar_handle_alloc(index, nullptr, &handle, &elements) == MPI_SUCCESS) {
      // a bool (Open MPI) or an int, read into room for either
      int read = 0;
      bool flag = false;
      if (MPI_T_cvar_read(handle, type == MPI_C_BOOL ? static_cast<void*>(&flag) : &read) ==
          MPI_SUCCESS)
        value = (flag || read != 0) ? 1 : 0;
      MPI_T_cvar_handle_free(&handle);
    }
  }
  MPI_T_finalize();
  return value;
}

void MpiContext::send(int destination, Tag tag, const std::vector<std::uint8_t>& bytes) {
  check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, destination,
                 static_cast<int>(tag), communicator_->comm),
        "MPI_Send", rank_);
}

void MpiContext::post(int destination, Tag tag, std::vector<std::uint8_t> bytes) {
  auto& send = posted_->sends.emplace_back();
  send.bytes = std::move(bytes);
  check(MPI_Isend(send.bytes.data(), static_cast<int>(send.bytes.size()), MPI_BYTE, destination,
                  static_cast<int>(tag), communicator_->comm, &send.request),
        "MPI_Isend", rank_);
}

std::size_t MpiContext::completePosted() {
  if (posted_->sends.empty())
    return 0;
  // one MPI_Testsome over every send (one progress call, however many are under way), then the
  // finished ones dropped with their bytes
  std::vector<MPI_Request> requests;
  requests.reserve(posted_->sends.size());
  for (const auto& send : posted_->sends)
    requests.push_back(send.request);
  std::vector<int> done(requests.size());
  int count = 0;
  check(MPI_Testsome(static_cast<int>(requests.size()), requests.data(), &count, done.data(),
                     MPI_STATUSES_IGNORE),
        "MPI_Testsome", rank_);
  if (count == MPI_UNDEFINED || count == 0)
    return posted_->sends.size();
  std::vector<char> finished(requests.size(), 0);
  for (int k = 0; k < count; ++k)
    finished[static_cast<std::size_t>(done[static_cast<std::size_t>(k)])] = 1;
  std::size_t i = 0;
  for (auto it = posted_->sends.begin(); it != posted_->sends.end(); ++i)
    it = finished[i] ? posted_->sends.erase(it) : std::next(it);
  return posted_->sends.size();
}

void MpiContext::waitPosted() {
  Backoff backoff;
  while (completePosted() > 0)
    backoff.wait();
}

bool MpiContext::tryReceiveAny(int source, Message& out) {
  // any tag, from `source` or (when negative) any rank
  return receiveWaiting(communicator_->comm, source < 0 ? MPI_ANY_SOURCE : source, MPI_ANY_TAG,
                        rank_, out);
}

bool MpiContext::tryReceive(Tag tag, Message& out) {
  // this tag, from any rank
  return receiveWaiting(communicator_->comm, MPI_ANY_SOURCE, static_cast<int>(tag), rank_, out);
}

Message MpiContext::receiveAny(int source, long longest_sleep_micros, long urgent_micros) {
  return waitFor([&](Message& message) { return tryReceiveAny(source, message); },
                 longest_sleep_micros, urgent_micros);
}

Message MpiContext::receive(Tag tag) {
  return waitFor([&](Message& message) { return tryReceive(tag, message); }, Backoff::kMax, 0);
}

int MpiContext::allReduceMax(int value) {
  int result = value;
  check(MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MAX, communicator_->comm), "MPI_Allreduce",
        rank_);
  return result;
}

std::uint64_t MpiContext::allReduceMax(std::uint64_t value) {
  std::uint64_t result = value;
  check(MPI_Allreduce(&value, &result, 1, MPI_UINT64_T, MPI_MAX, communicator_->comm),
        "MPI_Allreduce", rank_);
  return result;
}

std::vector<std::uint64_t> MpiContext::allGather(std::uint64_t value) {
  std::vector<std::uint64_t> values(static_cast<std::size_t>(size_));
  check(MPI_Allgather(&value, 1, MPI_UINT64_T, values.data(), 1, MPI_UINT64_T, communicator_->comm),
        "MPI_Allgather", rank_);
  return values;
}

void MpiContext::abort(ExitCode code, const std::string& message) const {
  // one write, so that mpirun's own abort notice cannot land inside the line
  std::cerr << ("cambrian evolve: rank " + std::to_string(rank_) + ": " + message + "\n")
            << std::flush;
  MPI_Abort(MPI_COMM_WORLD, static_cast<int>(code));
  std::_Exit(static_cast<int>(code));
}

void Backoff::wait() {
  // nanosleep, then grow the interval
  timespec interval{micros_ / 1000000, (micros_ % 1000000) * 1000};
  nanosleep(&interval, nullptr);
  micros_ = std::min(ceiling_, micros_ * 2);
}

}  // namespace cambrian
