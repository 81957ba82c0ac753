// Message counters per phase of a run, through the MPI profiling interface: a shared library
// that defines the MPI functions below, counts each call and forwards it to its PMPI_ twin.
// Load it with LD_PRELOAD (or link it before the MPI library) and name an output file:
//
//   mpirun -np 4 -x LD_PRELOAD=build/bench/libsignorini_mpi_counters.so
//          -x SIGNORINI_MPI_COUNTERS=counters.json build/bin/signorini problem.xml
//
// Phases. MPI_Pcontrol(level) with level in 0..15 makes level the current phase; other
// levels are ignored. Signorini calls it (src/core/CommunicationPhase.hpp) with 0 = other,
// 1 = mesh and space, 2 = assembly, 3 = solve (the interior point iterations but for 4 and 5),
// 4 = Krylov iterations with their preconditioner applications, 5 = preconditioner setup,
// 6 = output. A run starts in phase 0.
//
// What is counted. Calls on communicators of more than one rank only (a one-rank
// communicator moves no message); point-to-point calls to MPI_PROC_NULL are not counted.
// Bytes are counts times PMPI_Type_size:
//   sends (MPI_Send, Isend, Ssend, Rsend, the send of MPI_Sendrecv): the message sent;
//   receives (MPI_Recv, Irecv, the receive of MPI_Sendrecv, counted as the row
//     "MPI_Sendrecv:receive"): the size posted, which bounds the message received;
//   collectives: what this rank puts in, the part of its send buffer the operation reads:
//     Allreduce, Iallreduce, Reduce, Scan, Exscan and Bcast (on every rank) count * size;
//     Gather(v), Allgather(v) sendcount * size; Scatter(v) on the root every block sent,
//     elsewhere 0; Alltoall(v) every block, its own included; Barrier 0. With MPI_IN_PLACE
//     the rank's block of the receive buffer stands for its send buffer.
// Other MPI functions (persistent and buffered sends, one-sided, neighbourhood and other
// nonblocking collectives) pass through uncounted.
//
// Output. At MPI_Finalize, if SIGNORINI_MPI_COUNTERS is set on rank 0, rank 0 gathers every
// rank's counters (with PMPI calls, themselves uncounted) and writes that file:
//
//   {"format": "signorini-mpi-counters 1", "ranks": N,
//    "phases": {"other": PHASE, "mesh_and_space": PHASE, "assembly": PHASE, "solve": PHASE,
//               "krylov": PHASE, "preconditioner_setup": PHASE, "output": PHASE,
//               "level_7": PHASE ...  (levels 7..15 only when something was counted there)}}
//   PHASE = {"level": L,
//            "per_rank": [{"calls": {FUNCTION: n, ...}, "bytes": {FUNCTION: b, ...}}, ...],
//            "total": {"calls": {...}, "bytes": {...}},          (sums over the ranks)
//            "summary": {QUANTITY: {"total": sum over ranks, "max": max over ranks}, ...}}
//
// FUNCTION is an MPI function name (or "MPI_Sendrecv:receive"), listed when called at least
// once. The summary's quantities: messages_sent and bytes_sent (the send rows),
// messages_received and bytes_received (the receive rows), collectives and collective_bytes
// (every collective call, barriers included), allreduces (MPI_Allreduce and MPI_Iallreduce).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

enum Kind { kSend, kReceive, kCollective };
struct Row {
  const char* name;
  Kind kind;
};
enum Function {
  Send, Isend, Ssend, Rsend, Sendrecv, Recv, Irecv, SendrecvReceive, Allreduce, Iallreduce, Reduce, Bcast,
  Scan, Exscan, Barrier, Allgather, Allgatherv, Gather, Gatherv, Scatter, Scatterv, Alltoall, Alltoallv,
  kFunctions
};
const Row kRows[kFunctions] = {
    {"MPI_Send", kSend}, {"MPI_Isend", kSend}, {"MPI_Ssend", kSend}, {"MPI_Rsend", kSend},
    {"MPI_Sendrecv", kSend}, {"MPI_Recv", kReceive}, {"MPI_Irecv", kReceive},
    {"MPI_Sendrecv:receive", kReceive}, {"MPI_Allreduce", kCollective}, {"MPI_Iallreduce", kCollective},
    {"MPI_Reduce", kCollective}, {"MPI_Bcast", kCollective}, {"MPI_Scan", kCollective},
    {"MPI_Exscan", kCollective}, {"MPI_Barrier", kCollective}, {"MPI_Allgather", kCollective},
    {"MPI_Allgatherv", kCollective}, {"MPI_Gather", kCollective}, {"MPI_Gatherv", kCollective},
    {"MPI_Scatter", kCollective}, {"MPI_Scatterv", kCollective}, {"MPI_Alltoall", kCollective},
    {"MPI_Alltoallv", kCollective}};
constexpr int kPhases = 16;
const char* const kPhaseNames[] = {"other", "mesh_and_space", "assembly", "solve", "krylov",
                                   "preconditioner_setup", "output"};
constexpr int kNamedPhases = sizeof(kPhaseNames) / sizeof(kPhaseNames[0]);

// The counter table: calls and bytes per phase and function.
struct Counter {
  long long calls = 0, bytes = 0;
};
Counter table[kPhases][kFunctions];
int phase = 0;

long long bytes(long long count, MPI_Datatype type) {
  if (count == 0 || type == MPI_DATATYPE_NULL) return 0;
  int size = 0;
  PMPI_Type_size(type, &size);
  return count * size;
}
long long sum(const int* counts, int n) {
  long long s = 0;
  for (int i = 0; i < n; ++i) s += counts[i];
  return s;
}
int size(MPI_Comm comm) {
  int n = 0;
  PMPI_Comm_size(comm, &n);
  return n;
}
int rank(MPI_Comm comm) {
  int r = 0;
  PMPI_Comm_rank(comm, &r);
  return r;
}
void add(Function f, long long b) {
  ++table[phase][f].calls;
  table[phase][f].bytes += b;
}
// A point-to-point message of count elements of type to or from peer.
void message(Function f, int count, MPI_Datatype type, int peer, MPI_Comm comm) {
  if (peer != MPI_PROC_NULL && size(comm) > 1) add(f, bytes(count, type));
}
// A collective call on comm to which this rank contributes b bytes.
void collective(Function f, MPI_Comm comm, long long b) {
  if (size(comm) > 1) add(f, b);
}
bool inPlace(const void* sendbuf) { return sendbuf == MPI_IN_PLACE; }

}  // namespace

int MPI_Pcontrol(const int level, ...) {
  if (level >= 0 && level < kPhases) phase = level;
  return PMPI_Pcontrol(level);
}

// Point to point.
int MPI_Send(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm) {
  message(Send, count, type, dest, comm);
  return PMPI_Send(buf, count, type, dest, tag, comm);
}
int MPI_Isend(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm, MPI_Request* req) {
  message(Isend, count, type, dest, comm);
  return PMPI_Isend(buf, count, type, dest, tag, comm, req);
}
int MPI_Ssend(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm) {
  message(Ssend, count, type, dest, comm);
  return PMPI_Ssend(buf, count, type, dest, tag, comm);
}
int MPI_Rsend(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm) {
  message(Rsend, count, type, dest, comm);
  return PMPI_Rsend(buf, count, type, dest, tag, comm);
}
int MPI_Recv(void* buf, int count, MPI_Datatype type, int source, int tag, MPI_Comm comm, MPI_Status* status) {
  message(Recv, count, type, source, comm);
  return PMPI_Recv(buf, count, type, source, tag, comm, status);
}
int MPI_Irecv(void* buf, int count, MPI_Datatype type, int source, int tag, MPI_Comm comm, MPI_Request* req) {
  message(Irecv, count, type, source, comm);
  return PMPI_Irecv(buf, count, type, source, tag, comm, req);
}
int MPI_Sendrecv(const void* sendbuf, int sendcount, MPI_Datatype sendtype, int dest, int sendtag, void* recvbuf,
                 int recvcount, MPI_Datatype recvtype, int source, int recvtag, MPI_Comm comm, MPI_Status* status) {
  message(Sendrecv, sendcount, sendtype, dest, comm);
  message(SendrecvReceive, recvcount, recvtype, source, comm);
  return PMPI_Sendrecv(sendbuf, sendcount, sendtype, dest, sendtag, recvbuf, recvcount, recvtype, source, recvtag,
                       comm, status);
}

// Collectives: each adds its call and the bytes this rank puts in (see the top of the file).
int MPI_Allreduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype type, MPI_Op op, MPI_Comm comm) {
  collective(Allreduce, comm, bytes(count, type));
  return PMPI_Allreduce(sendbuf, recvbuf, count, type, op, comm);
}
int MPI_Iallreduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype type, MPI_Op op, MPI_Comm comm,
                   MPI_Request* req) {
  collective(Iallreduce, comm, bytes(count, type));
  return PMPI_Iallreduce(sendbuf, recvbuf, count, type, op, comm, req);
}
int MPI_Reduce(const void* sendbuf, void* recvbuf, int count, MPI_Datatype type, MPI_Op op, int root,
               MPI_Comm comm) {
  collective(Reduce, comm, bytes(count, type));
  return PMPI_Reduce(sendbuf, recvbuf, count, type, op, root, comm);
}
int MPI_Bcast(void* buf, int count, MPI_Datatype type, int root, MPI_Comm comm) {
  collective(Bcast, comm, bytes(count, type));
  return PMPI_Bcast(buf, count, type, root, comm);
}
int MPI_Scan(const void* sendbuf, void* recvbuf, int count, MPI_Datatype type, MPI_Op op, MPI_Comm comm) {
  collective(Scan, comm, bytes(count, type));
  return PMPI_Scan(sendbuf, recvbuf, count, type, op, comm);
}
int MPI_Exscan(const void* sendbuf, void* recvbuf, int count, MPI_Datatype type, MPI_Op op, MPI_Comm comm) {
  collective(Exscan, comm, bytes(count, type));
  return PMPI_Exscan(sendbuf, recvbuf, count, type, op, comm);
}
int MPI_Barrier(MPI_Comm comm) {
  collective(Barrier, comm, 0);
  return PMPI_Barrier(comm);
}
int MPI_Allgather(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                  MPI_Datatype recvtype, MPI_Comm comm) {
  collective(Allgather, comm, inPlace(sendbuf) ? bytes(recvcount, recvtype) : bytes(sendcount, sendtype));
  return PMPI_Allgather(sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, comm);
}
int MPI_Allgatherv(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, const int recvcounts[],
                   const int displs[], MPI_Datatype recvtype, MPI_Comm comm) {
  collective(Allgatherv, comm,
             inPlace(sendbuf) ? bytes(recvcounts[rank(comm)], recvtype) : bytes(sendcount, sendtype));
  return PMPI_Allgatherv(sendbuf, sendcount, sendtype, recvbuf, recvcounts, displs, recvtype, comm);
}
int MPI_Gather(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
               MPI_Datatype recvtype, int root, MPI_Comm comm) {
  collective(Gather, comm, inPlace(sendbuf) ? bytes(recvcount, recvtype) : bytes(sendcount, sendtype));
  return PMPI_Gather(sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, root, comm);
}
int MPI_Gatherv(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, const int recvcounts[],
                const int displs[], MPI_Datatype recvtype, int root, MPI_Comm comm) {
  collective(Gatherv, comm, inPlace(sendbuf) ? bytes(recvcounts[root], recvtype) : bytes(sendcount, sendtype));
  return PMPI_Gatherv(sendbuf, sendcount, sendtype, recvbuf, recvcounts, displs, recvtype, root, comm);
}
int MPI_Scatter(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                MPI_Datatype recvtype, int root, MPI_Comm comm) {
  const int ranks = size(comm);
  if (ranks > 1) add(Scatter, rank(comm) == root ? bytes(1LL * sendcount * ranks, sendtype) : 0);
  return PMPI_Scatter(sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, root, comm);
}
int MPI_Scatterv(const void* sendbuf, const int sendcounts[], const int displs[], MPI_Datatype sendtype,
                 void* recvbuf, int recvcount, MPI_Datatype recvtype, int root, MPI_Comm comm) {
  const int ranks = size(comm);
  if (ranks > 1) add(Scatterv, rank(comm) == root ? bytes(sum(sendcounts, ranks), sendtype) : 0);
  return PMPI_Scatterv(sendbuf, sendcounts, displs, sendtype, recvbuf, recvcount, recvtype, root, comm);
}
int MPI_Alltoall(const void* sendbuf, int sendcount, MPI_Datatype sendtype, void* recvbuf, int recvcount,
                 MPI_Datatype recvtype, MPI_Comm comm) {
  const int ranks = size(comm);
  if (ranks > 1)
    add(Alltoall, inPlace(sendbuf) ? bytes(1LL * recvcount * ranks, recvtype)
                                   : bytes(1LL * sendcount * ranks, sendtype));
  return PMPI_Alltoall(sendbuf, sendcount, sendtype, recvbuf, recvcount, recvtype, comm);
}
int MPI_Alltoallv(const void* sendbuf, const int sendcounts[], const int sdispls[], MPI_Datatype sendtype,
                  void* recvbuf, const int recvcounts[], const int rdispls[], MPI_Datatype recvtype, MPI_Comm comm) {
  const int ranks = size(comm);
  if (ranks > 1)
    add(Alltoallv, inPlace(sendbuf) ? bytes(sum(recvcounts, ranks), recvtype)
                                    : bytes(sum(sendcounts, ranks), sendtype));
  return PMPI_Alltoallv(sendbuf, sendcounts, sdispls, sendtype, recvbuf, recvcounts, rdispls, recvtype, comm);
}

namespace {

// all[r] is rank r's table, flattened as [phase][function][calls, bytes].
using Tables = std::vector<std::vector<long long>>;
long long at(const Tables& all, int r, int p, int f, int column) { return all[r][(p * kFunctions + f) * 2 + column]; }
int ranks(const Tables& all) { return static_cast<int>(all.size()); }

// The quantities of the per-rank entries and the summary: sums of one column (0 calls,
// 1 bytes) over some rows.
struct Quantity {
  const char* name;
  bool (*counts)(int f);
  int column;
};
const Quantity kQuantities[] = {
    {"messages_sent", [](int f) { return kRows[f].kind == kSend; }, 0},
    {"bytes_sent", [](int f) { return kRows[f].kind == kSend; }, 1},
    {"messages_received", [](int f) { return kRows[f].kind == kReceive; }, 0},
    {"bytes_received", [](int f) { return kRows[f].kind == kReceive; }, 1},
    {"collectives", [](int f) { return kRows[f].kind == kCollective; }, 0},
    {"collective_bytes", [](int f) { return kRows[f].kind == kCollective; }, 1},
    {"allreduces", [](int f) { return f == Allreduce || f == Iallreduce; }, 0}};
long long quantity(const Tables& all, int r, int p, const Quantity& q) {
  long long sum = 0;
  for (int f = 0; f < kFunctions; ++f)
    if (q.counts(f)) sum += at(all, r, p, f, q.column);
  return sum;
}

// "calls": {"MPI_X": n, ...}, "bytes": {...} over the functions called at least once, by
// rank r or, for r < 0, by all ranks together.
void writeCounts(FILE* out, const Tables& all, int r, int p) {
  for (int column : {0, 1}) {
    std::fprintf(out, column == 0 ? "\"calls\": {" : ", \"bytes\": {");
    const char* separator = "";
    for (int f = 0; f < kFunctions; ++f) {
      long long calls = 0, value = 0;
      for (int q = 0; q < ranks(all); ++q)
        if (r < 0 || q == r) calls += at(all, q, p, f, 0), value += at(all, q, p, f, column);
      if (calls == 0) continue;
      std::fprintf(out, "%s\"%s\": %lld", separator, kRows[f].name, value);
      separator = ", ";
    }
    std::fprintf(out, "}");
  }
}

void writePhase(FILE* out, const Tables& all, int p) {
  std::fprintf(out, "{\"level\": %d,\n  \"per_rank\": [", p);
  for (int r = 0; r < ranks(all); ++r) {
    std::fprintf(out, "%s\n   {", r ? "," : "");
    writeCounts(out, all, r, p);
    for (const Quantity& q : kQuantities) std::fprintf(out, ", \"%s\": %lld", q.name, quantity(all, r, p, q));
    std::fprintf(out, "}");
  }
  std::fprintf(out, "],\n  \"total\": {");
  writeCounts(out, all, -1, p);
  std::fprintf(out, "},\n  \"summary\": {");
  for (const Quantity& q : kQuantities) {
    long long total = 0, max = 0;
    for (int r = 0; r < ranks(all); ++r) {
      total += quantity(all, r, p, q);
      max = std::max(max, quantity(all, r, p, q));
    }
    std::fprintf(out, "%s\n   \"%s\": {\"total\": %lld, \"max\": %lld}", &q == kQuantities ? "" : ",", q.name,
                 total, max);
  }
  std::fprintf(out, "}}");
}

void write(const char* path, const Tables& all) {
  FILE* out = std::fopen(path, "w");
  if (!out) {
    std::fprintf(stderr, "mpi_counters: cannot write %s\n", path);
    return;
  }
  std::fprintf(out, "{\"format\": \"signorini-mpi-counters 1\", \"ranks\": %d, \"phases\": {", ranks(all));
  const char* separator = "\n";
  for (int p = 0; p < kPhases; ++p) {
    bool used = false;
    for (int r = 0; r < ranks(all); ++r)
      for (int f = 0; f < kFunctions; ++f) used = used || at(all, r, p, f, 0) > 0;
    if (p >= kNamedPhases && !used) continue;
    if (p < kNamedPhases)
      std::fprintf(out, "%s \"%s\": ", separator, kPhaseNames[p]);
    else
      std::fprintf(out, "%s \"level_%d\": ", separator, p);
    writePhase(out, all, p);
    separator = ",\n";
  }
  std::fprintf(out, "}}\n");
  std::fclose(out);
}

}  // namespace

int MPI_Finalize() {
  const char* path = std::getenv("SIGNORINI_MPI_COUNTERS");
  int wanted = path && *path;
  PMPI_Bcast(&wanted, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (wanted) {
    const int ranks = size(MPI_COMM_WORLD), me = rank(MPI_COMM_WORLD);
    const int n = kPhases * kFunctions * 2;
    std::vector<long long> mine(n), gathered(me == 0 ? static_cast<size_t>(n) * ranks : 0);
    for (int p = 0; p < kPhases; ++p)
      for (int f = 0; f < kFunctions; ++f) {
        mine[(p * kFunctions + f) * 2] = table[p][f].calls;
        mine[(p * kFunctions + f) * 2 + 1] = table[p][f].bytes;
      }
    PMPI_Gather(mine.data(), n, MPI_LONG_LONG, gathered.data(), n, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
    if (me == 0) {
      Tables all(ranks);
      for (int r = 0; r < ranks; ++r) all[r].assign(gathered.begin() + r * n, gathered.begin() + (r + 1) * n);
      write(path, all);
    }
  }
  return PMPI_Finalize();
}
