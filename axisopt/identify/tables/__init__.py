"""Diagnosis of reduced measurement tables (stiffness or friction against position, load, speed):
the reader (:mod:`.data`), the measurement model of the axis (:mod:`.measure`), the forward
selection of effects by BIC and grouped cross-validation (:mod:`.diagnose`), what remains
unexplained (:mod:`.unexplained`) and the tests' simulator (:mod:`.synth`).  The effects, the fit,
the selection rule and the plant are shared with the time records (:mod:`axisopt.identify`)."""
