#pragma once
/// \file
/// Signorini's public API in one include. Each header can also be included on its own:
///   core/       errors, Tpetra type aliases, version
///   solver/     the contact QP, the interior point solver, its result and observers
///   fe/         the material law
///   assembly/   the problem definition, expressions, contact pressure and statistics
///   problem/    the "Problem" parameter list and the builder from it to an assembled QP
///   io/         ParaView output
#include "signorini/assembly/ContactPressure.hpp"
#include "signorini/assembly/ContactStatistics.hpp"
#include "signorini/assembly/Expression.hpp"
#include "signorini/assembly/FiniteElementSpace.hpp"
#include "signorini/assembly/ProblemDefinition.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/GeometricGrid.hpp"
#include "signorini/core/TpetraTypes.hpp"
#include "signorini/core/Version.hpp"
#include "signorini/fe/IsotropicMaterial.hpp"
#include "signorini/io/QPFiles.hpp"
#include "signorini/io/SolutionOutput.hpp"
#include "signorini/io/VtuWriter.hpp"
#include "signorini/problem/ProblemBuilder.hpp"
#include "signorini/problem/ProblemParameters.hpp"
#include "signorini/solver/ContactQP.hpp"
#include "signorini/solver/InteriorPointSolver.hpp"
#include "signorini/solver/IterationObserver.hpp"
#include "signorini/solver/KKTMeasures.hpp"
#include "signorini/solver/MultigridInput.hpp"
#include "signorini/solver/SimplexGrid.hpp"
#include "signorini/solver/SolveRecorder.hpp"
#include "signorini/solver/SolveResult.hpp"
#include "signorini/solver/StiffnessOperator.hpp"
