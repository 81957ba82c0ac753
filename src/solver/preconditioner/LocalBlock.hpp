#pragma once
// Blocks of distributed matrices and vectors copied onto one-rank communicators: Debian's
// Amesos2 solvers are wrong on communicators of more than one rank, so what they factor is
// first gathered (to rank 0, or each rank its own block) and handed over on MPI_COMM_SELF.
#include <functional>

#include "signorini/core/TpetraTypes.hpp"

namespace signorini {

// MPI_COMM_SELF as a Teuchos communicator.
RCP<const Comm> selfComm();

// The rows of M imported to `blockRows` through `importer`, with the columns whose global id
// `columnIndex` maps to an index >= 0, renumbered so: a matrix on the one-rank maps
// `localRows` x `localColumns` where `localRows` is not null, null elsewhere. Collective.
RCP<CrsMatrix> importedBlock(const CrsMatrix& M, const RCP<const Map>& blockRows, const Import& importer,
                              const std::function<LocalOrdinal(GlobalOrdinal)>& columnIndex,
                              const RCP<const Map>& localRows, const RCP<const Map>& localColumns);

// Copies the local rows of `from` into `to` (same local length and number of columns).
void copyLocalRows(const MultiVector& from, MultiVector& to);

}  // namespace signorini
