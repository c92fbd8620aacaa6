"""Qt-free teaching tools built on the model: exercises a student answers on
the grid, checking a student's own algorithm against the hard cases, and
worksheets to print.

``exercise``           the exercise mode's questions and grading
``student``            runs a student's program in a child process, with limits
``student_child``      what runs in that child (the runner, self-contained)
``sandbox``            where that child runs: a bubblewrap sandbox, or the fallback
``student_answer``     the child's answer, read as untrusted input
``checking``           a student's algorithm against the hard cases and the exact oracles
``check_families``     what checking asks of each family
``check_report``       a check's outcome as text, JSON or JUnit
``batch``              a class's submissions graded on the same cases, several at a time
``grade_formats``      a class's results for graders: Gradescope, PrairieLearn, CodeRunner, JUnit, CSV
``grade_pictures``     a failing case's pixel difference as a PNG or an SVG
``autograder``         Gradescope's autograder zip
``student_algorithm``  a student's file as an algorithm the window can step through
``worksheet``          a scene's steps as a table to fill in, with its answer key
"""
