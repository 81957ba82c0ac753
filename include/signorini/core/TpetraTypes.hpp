#pragma once
/// \file
/// The Tpetra types Signorini works with: Debian's Trilinos is instantiated for
/// <double, int, long long> on the Kokkos Serial node.
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_Export_fwd.hpp>
#include <Tpetra_Import_fwd.hpp>
#include <Tpetra_Map_fwd.hpp>
#include <Tpetra_MultiVector_fwd.hpp>
#include <Tpetra_Operator_fwd.hpp>
#include <Tpetra_Vector_fwd.hpp>
#include <Tpetra_Details_DefaultTypes.hpp>

namespace signorini {

using Scalar = double;
using LocalOrdinal = int;
using GlobalOrdinal = long long;
using Node = Tpetra::Details::DefaultTypes::node_type;

using Map = Tpetra::Map<LocalOrdinal, GlobalOrdinal, Node>;
using Import = Tpetra::Import<LocalOrdinal, GlobalOrdinal, Node>;
using Export = Tpetra::Export<LocalOrdinal, GlobalOrdinal, Node>;
using Operator = Tpetra::Operator<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using CrsMatrix = Tpetra::CrsMatrix<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using MultiVector = Tpetra::MultiVector<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using Vector = Tpetra::Vector<Scalar, LocalOrdinal, GlobalOrdinal, Node>;
using Comm = Teuchos::Comm<int>;

using Teuchos::RCP;
using Teuchos::rcp;

}  // namespace signorini
