#pragma once
// A nodal field's values given from outside the model at each time (Peridigm's Data Loader: a field read from a
// file). FieldSet asks its source wherever it imposes the field's conditions (the run's start, every evaluation),
// so the field is prescribed at every node and is committed, checkpointed and written like any other.
namespace pf {

class FieldSource {
 public:
  virtual ~FieldSource() = default;
  // The field's value at time t of every owned node (one per owned node). Every rank calls it at the same times.
  virtual void valuesAt(double t, double* values) = 0;
};

}  // namespace pf
