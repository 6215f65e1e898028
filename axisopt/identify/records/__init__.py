"""Diagnosis of time records (motor torque, position, speed over time): the reader and filters
(:mod:`.record`), the inverse-dynamics regression terms and rows (:mod:`.regression`), least squares
and closed-loop instrumental variables (:mod:`.estimators`), lost motion (:mod:`.lostmotion`), the
probes of the residual (:mod:`.signature`, :mod:`.unexplained`), the forward selection
(:mod:`.idim`), the calibration written from it (:mod:`.calibration`) and an independent closed-loop
simulator for the tests (:mod:`.synth`).  The effects, the selection rule and the calibration file
are shared with the tables (:mod:`axisopt.identify`)."""
