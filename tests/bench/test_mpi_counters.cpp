// The message counters of bench/mpi_counters.cpp, linked into this program ahead of the MPI
// library: a known sequence of calls on 2 ranks, in phases set with MPI_Pcontrol; after
// MPI_Finalize rank 0 reads the JSON file the counters wrote and checks every number in it.
//
//   mpirun -np 2 build/tests/test_mpi_counters    (SIGNORINI_MPI_COUNTERS names the file;
//                                                   test_mpi_counters.json by default)
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

// The numbers of a JSON text by path ("phases.krylov.per_rank.0.calls.MPI_Send"); strings,
// booleans and nulls are checked for syntax only.
class FlatJson {
 public:
  explicit FlatJson(const std::string& text) : p_(text.c_str()) {
    value("");
    space();
    if (*p_) fail("text after the value");
  }
  std::map<std::string, double> numbers;

 private:
  const char* p_;
  [[noreturn]] void fail(const char* what) { throw std::runtime_error(std::string("JSON: ") + what); }
  void space() {
    while (*p_ == ' ' || *p_ == '\n' || *p_ == '\t' || *p_ == '\r') ++p_;
  }
  void expect(char c) {
    space();
    if (*p_++ != c) fail("unexpected character");
  }
  std::string string() {
    expect('"');
    std::string s;
    while (*p_ && *p_ != '"') s += *p_ == '\\' ? *++p_ : *p_, ++p_;
    expect('"');
    return s;
  }
  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }
  void value(const std::string& path) {
    space();
    if (*p_ == '{' || *p_ == '[') {
      const char close = *p_ == '{' ? '}' : ']';
      ++p_;
      space();
      for (int index = 0; *p_ != close; ++index) {
        if (index > 0) expect(',');
        if (close == '}') {
          const std::string key = string();
          expect(':');
          value(join(path, key));
        } else {
          value(join(path, std::to_string(index)));
        }
        space();
      }
      ++p_;
    } else if (*p_ == '"') {
      string();
    } else if (!std::strncmp(p_, "true", 4) || !std::strncmp(p_, "null", 4)) {
      p_ += 4;
    } else if (!std::strncmp(p_, "false", 5)) {
      p_ += 5;
    } else {
      char* end = nullptr;
      numbers[path] = std::strtod(p_, &end);
      if (end == p_) fail("not a value");
      p_ = end;
    }
  }
};

const char* const kPhases[] = {"other", "mesh_and_space", "assembly", "solve", "krylov",
                               "preconditioner_setup", "output", "level_9"};
const char* const kQuantities[] = {"messages_sent", "bytes_sent", "messages_received", "bytes_received",
                                   "collectives", "collective_bytes", "allreduces"};

// Every number the file must hold, and no other.
std::map<std::string, double> expected() {
  std::map<std::string, double> e{{"ranks", 2}};
  for (const char* phase : kPhases)
    for (const char* q : kQuantities)
      for (const char* of : {"summary.%s.total", "summary.%s.max", "per_rank.0.%s", "per_rank.1.%s"}) {
        char key[128];
        std::snprintf(key, sizeof key, of, q);
        e[std::string("phases.") + phase + "." + key] = 0;
      }
  for (int level = 0; level < 7; ++level) e[std::string("phases.") + kPhases[level] + ".level"] = level;
  e["phases.level_9.level"] = 9;
  // Phase krylov: 3 all-reduces of 5 doubles on each rank, 2 messages of 10 ints from 0 to 1.
  auto set = [&e](const std::string& phase, const std::string& rest, double v) {
    e["phases." + phase + "." + rest] = v;
  };
  for (const char* r : {"per_rank.0.", "per_rank.1."}) {
    set("krylov", std::string(r) + "calls.MPI_Allreduce", 3);
    set("krylov", std::string(r) + "bytes.MPI_Allreduce", 3 * 5 * 8);
  }
  set("krylov", "per_rank.0.calls.MPI_Send", 2);
  set("krylov", "per_rank.0.bytes.MPI_Send", 2 * 10 * 4);
  set("krylov", "per_rank.1.calls.MPI_Recv", 2);
  set("krylov", "per_rank.1.bytes.MPI_Recv", 2 * 10 * 4);
  set("krylov", "total.calls.MPI_Allreduce", 6);
  set("krylov", "total.bytes.MPI_Allreduce", 240);
  set("krylov", "total.calls.MPI_Send", 2);
  set("krylov", "total.bytes.MPI_Send", 80);
  set("krylov", "total.calls.MPI_Recv", 2);
  set("krylov", "total.bytes.MPI_Recv", 80);
  for (const char* q : {"messages_sent", "messages_received"})
    for (const char* of : {".total", ".max"}) set("krylov", std::string("summary.") + q + of, 2);
  for (const char* q : {"bytes_sent", "bytes_received"})
    for (const char* of : {".total", ".max"}) set("krylov", std::string("summary.") + q + of, 80);
  set("krylov", "summary.collectives.total", 6);
  set("krylov", "summary.collectives.max", 3);
  set("krylov", "summary.allreduces.total", 6);
  set("krylov", "summary.allreduces.max", 3);
  set("krylov", "summary.collective_bytes.total", 240);
  set("krylov", "summary.collective_bytes.max", 120);
  for (const char* r : {"per_rank.0.", "per_rank.1."}) {
    set("krylov", std::string(r) + "collectives", 3);
    set("krylov", std::string(r) + "collective_bytes", 120);
    set("krylov", std::string(r) + "allreduces", 3);
  }
  set("krylov", "per_rank.0.messages_sent", 2);
  set("krylov", "per_rank.0.bytes_sent", 80);
  set("krylov", "per_rank.1.messages_received", 2);
  set("krylov", "per_rank.1.bytes_received", 80);
  // Phase other: one barrier on each rank.
  for (const char* r : {"per_rank.0.", "per_rank.1."}) {
    set("other", std::string(r) + "calls.MPI_Barrier", 1);
    set("other", std::string(r) + "bytes.MPI_Barrier", 0);
    set("other", std::string(r) + "collectives", 1);
  }
  set("other", "total.calls.MPI_Barrier", 2);
  set("other", "total.bytes.MPI_Barrier", 0);
  set("other", "summary.collectives.total", 2);
  set("other", "summary.collectives.max", 1);
  // Level 9: each rank exchanges 3 doubles with the other in one MPI_Sendrecv.
  for (const char* r : {"per_rank.0.", "per_rank.1."}) {
    for (const char* f : {"MPI_Sendrecv", "MPI_Sendrecv:receive"}) {
      set("level_9", std::string(r) + "calls." + f, 1);
      set("level_9", std::string(r) + "bytes." + f, 24);
    }
    for (const char* q : {"messages_sent", "messages_received"}) set("level_9", r + std::string(q), 1);
    for (const char* q : {"bytes_sent", "bytes_received"}) set("level_9", r + std::string(q), 24);
  }
  for (const char* f : {"MPI_Sendrecv", "MPI_Sendrecv:receive"}) {
    set("level_9", std::string("total.calls.") + f, 2);
    set("level_9", std::string("total.bytes.") + f, 48);
  }
  for (const char* q : {"messages_sent", "messages_received"}) {
    set("level_9", std::string("summary.") + q + ".total", 2);
    set("level_9", std::string("summary.") + q + ".max", 1);
  }
  for (const char* q : {"bytes_sent", "bytes_received"}) {
    set("level_9", std::string("summary.") + q + ".total", 48);
    set("level_9", std::string("summary.") + q + ".max", 24);
  }
  return e;
}

// The calls the expected numbers describe, and some that must not count.
void communicate(int rank) {
  double five[5] = {1, 2, 3, 4, 5}, sum[5];
  int ten[10] = {};
  MPI_Pcontrol(4);
  for (int i = 0; i < 3; ++i) MPI_Allreduce(five, sum, 5, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  for (int i = 0; i < 2; ++i) {
    if (rank == 0) MPI_Send(ten, 10, MPI_INT, 1, i, MPI_COMM_WORLD);
    if (rank == 1) MPI_Recv(ten, 10, MPI_INT, 0, i, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
  // Not communication: a one-rank communicator, a message to MPI_PROC_NULL.
  MPI_Allreduce(five, sum, 5, MPI_DOUBLE, MPI_SUM, MPI_COMM_SELF);
  MPI_Bcast(ten, 10, MPI_INT, 0, MPI_COMM_SELF);
  MPI_Barrier(MPI_COMM_SELF);
  MPI_Send(ten, 10, MPI_INT, MPI_PROC_NULL, 0, MPI_COMM_WORLD);
  MPI_Pcontrol(16);  // levels outside 0..15 leave the phase as it is
  MPI_Pcontrol(-1);
  MPI_Send(ten, 10, MPI_INT, MPI_PROC_NULL, 0, MPI_COMM_WORLD);
  MPI_Pcontrol(0);
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Pcontrol(9);
  double three[3] = {1, 2, 3}, got[3];
  MPI_Sendrecv(three, 3, MPI_DOUBLE, 1 - rank, 7, got, 3, MPI_DOUBLE, 1 - rank, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Pcontrol(0);
}

int check(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "test_mpi_counters: no counters file %s\n", path.c_str());
    return 1;
  }
  std::stringstream text;
  text << in.rdbuf();
  std::map<std::string, double> found;
  try {
    found = FlatJson(text.str()).numbers;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "test_mpi_counters: %s: %s\n", path.c_str(), e.what());
    return 1;
  }
  const std::map<std::string, double> want = expected();
  int failures = 0;
  for (const auto& [key, value] : want) {
    const auto it = found.find(key);
    if (it == found.end())
      std::fprintf(stderr, "missing %s (expected %g)\n", key.c_str(), value), ++failures;
    else if (it->second != value)
      std::fprintf(stderr, "%s = %g, expected %g\n", key.c_str(), it->second, value), ++failures;
  }
  for (const auto& [key, value] : found)
    if (!want.count(key)) std::fprintf(stderr, "unexpected %s = %g\n", key.c_str(), value), ++failures;
  std::printf("test_mpi_counters: %zu numbers checked, %d failure(s)\n", want.size(), failures);
  return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size != 2) {
    if (rank == 0) std::fprintf(stderr, "test_mpi_counters: runs on 2 ranks, not %d\n", size);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  const char* named = std::getenv("SIGNORINI_MPI_COUNTERS");
  const std::string path = named && *named ? named : "test_mpi_counters.json";
  if (rank == 0) {
    std::remove(path.c_str());
    setenv("SIGNORINI_MPI_COUNTERS", path.c_str(), 1);  // the counters read it on rank 0
  }
  communicate(rank);
  MPI_Finalize();
  return rank == 0 ? check(path) : 0;
}
