"""The answers to an infeasible problem: why nothing fits (:mod:`.explain`: the limits no
combination meets and the closest designs), what to relax (:mod:`.relax`), the axis change a search
verifies (:mod:`.advice`), the mounting or catalog filter value the problem left out (:mod:`.widen`)
and the search budget they share (:mod:`.budget`).  The solve's stages never import this package;
the front door calls it when a solve finds nothing."""
