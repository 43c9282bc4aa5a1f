// The record or replay shim of one lab (compiled once per lab and role by cmake/GeolabLab.cmake):
//   -DGEOLAB_BOUNDARY_ROLE=record  the performer's recorder: each thunk calls the student's function and records
//   -DGEOLAB_BOUNDARY_ROLE=replay  the judge's replayer: each thunk answers from the recording
//   -DGEOLAB_LAB_HEADER=<geolab/halfedge.hpp>  the lab's API header, whose GEOLAB_BOUNDARY list is expanded here
// cmake/GeolabBoundary.cmake then renames each thunk to the student function's own symbol.
#include "geolab/grading/boundary_calls.hpp"

#define GEOLAB_BOUNDARY(name, ...) GEOLAB_BOUNDARY_ENTRY(GEOLAB_BOUNDARY_ROLE, name, __VA_ARGS__)
#include GEOLAB_LAB_HEADER
