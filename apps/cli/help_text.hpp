#pragma once
// What `flexmoor --help` and `flexmoor COMMAND --help` teach, beyond the options that the
// argument parser lists itself.

namespace flexmoor::cli {

inline constexpr const char* kDescription =
    "flexmoor - nonlinear finite-element analysis of cables, mooring lines and membranes";

inline constexpr const char* kOverview = R"(
A case is one YAML file that states a whole problem: its unit system, materials and sections,
the mesh (nodes, lines, elements, surfaces), supports, loads and load histories, the water
(waves, current, seabed, buoys and clump weights), the analysis steps to run in order, and the
summary quantities, figure and output fields to report; or a scenario (single_point_moor,
submerged_tube, spread_mooring) that states a whole model in a few keys. CASE is the path of
such a file or the name of a named case: its file name without .yaml, for example
ex1-suspended-cable-8xL2 ('flexmoor cases' lists them all with their titles; they are in
share/flexmoor/cases of the installation, cases/ of the source, or cases/ of the folder
FLEXMOOR_DATA_DIR names); '.yaml' may be left off a path too. A name that is not there is refused with the nearest ones ("did you
mean ...?").

Units: a case states `units: US` (ft, slug, s; forces in lbf) or `units: SI` (m, kg, s; N).
Any value may carry its own unit ("0.163 in", "500000 psi", "9.81 m/s^2") and is
converted once, on reading, into the case's system.

Steps run in order, each from the state the previous one left:
  relax    viscous relaxation (Appendix C) from an unstressed start to equilibrium
  static   load increments by Newton-Raphson, modified Newton, BFGS or the self-corrective
           scheme, or arc length
  modes    natural frequencies and mode shapes about the current, prestressed state
  dynamic  Newmark or HHT-alpha time steps with Newton iterations, fixed or chosen by their
           accuracy

'flexmoor run' writes into DIR (-o DIR; default results/<case>/):
  DIR/<case>.nc        netCDF-4 following the CF 1.8 conventions: time, node, element, end and
                       line coordinates, displacements, velocities, reactions, tensions, membrane
                       resultants and mode shapes, with units; the dynamic steps' records along
                       time (strictly increasing), the states closing the other steps along
                       stage (by step number), flushed as it goes; each node's and element's
                       line and arc length. `output: {fields: [position, tension]}`
                       in the case keeps only those fields in the records (a long run
                       written every step is mostly its records)
  DIR/<case>-<n>.vtk   the deformed shape (and mode shapes) after step n, for ParaView
  DIR/<case>.summary.json  the case's summary quantities with their units
Every output's name starts with the case's, so cases can share one -o DIR. Outputs are put in
place by a rename when the run ends: the netCDF streams into DIR/<case>.nc.partial, so a failed
or killed run never spoils an earlier DIR/<case>.nc; a second run of the case into DIR at once
is refused (the lock DIR/.<case>.lock).
'flexmoor plot' draws a figure of a run or a study as a PNG: time series, a spectrum against the
sea's target, line shapes, response-amplitude curves, extremes and response spectra;
'flexmoor study' runs a base case under many variations (sea states, seeds, any case value) and
gathers their statistics.

Exit codes:
  0  done (for check: the case is valid)
  1  usage error (an unknown command or option, a missing or extra argument)
  2  the case is invalid: every problem is listed on stderr as FILE:LINE: what is wrong
  3  a step did not converge: the last converged state is written, the diagnosis is on stderr
  4  the run failed otherwise (an output could not be written, a value was not finite,
     another run of the case is writing into DIR)

Examples:
  flexmoor cases
  flexmoor check cases/seed/ex1-suspended-cable-4xL3.yaml
  flexmoor run ex1-suspended-cable-8xL2     # results in results/ex1-suspended-cable-8xL2/
  flexmoor run -o runs/ex1 ex1-suspended-cable-8xL2 --no-vtk

'flexmoor COMMAND --help' tells more about one command. The case-file format, every key with
its default, is described in README.md (section "Case files"), and every case under cases/ is a
worked example.
)";

inline constexpr const char* kRunSummary = "run a case and write its results";

inline constexpr const char* kRunDetails =
    R"(
Reads and checks CASE as 'flexmoor check' does (an invalid case runs nothing and exits 2), then
runs its steps in order, each from the state the previous one left:
  relax    viscous relaxation (Appendix C) carries an unstable, unstressed start to equilibrium
  static   load increments up to the step's load_factor, by Newton-Raphson, modified Newton,
           BFGS or the self-corrective scheme (Eq. 5.1 convergence), or arc length through
           limit points (control: arc_length)
  modes    the lowest natural frequencies and mode shapes about the current, prestressed state
  dynamic  Newmark (Eq. 4.55-4.63) or HHT-alpha time steps with Newton iterations, fixed
           (dt with steps or duration, or a schedule of {dt, steps}) or, given a duration
           alone, each step chosen by its accuracy; a Newton increment that raises the
           residual is halved (backtracking), a step that fails is halved and retried;
           progress is logged
)"
    // How loads and load factors pass from step to step (libstruct/solve).
    R"(
Loads from step to step: a load with a history is its value times the history at the current
time. Gravity, nodal loads, pressures and prescribed displacements without one are scaled by
the load factor, which is 0 at the start of a run: static steps ramp it to their load_factor
(default 1), relax steps set it (default 1), modes steps keep it, and a dynamic step holds one
throughout: its load_factor, else the previous step's, or 1 if no earlier step set one. A
dynamic step after another continues its motion; static and relax steps end at rest.
)"
    R"(
Outputs, in DIR (default results/<case>/):
  DIR/<case>.nc        netCDF-4 following the CF 1.8 conventions: a dynamic step's records along
                       time, a static, relax or modes step's closing state along stage (by step
                       number), flushed as it goes; written by a second thread while the
                       run goes on when it streams 1,000 records or more (not with
                       --no-writer-thread)
  DIR/<case>-<n>.vtk   the deformed shape (and mode shapes) after step n (not with --no-vtk)
  DIR/<case>.summary.json  the case's summary quantities with their units
Every output's name starts with the case's, so cases can share one -o DIR. Outputs are put in
place by a rename when the run ends: the netCDF streams into DIR/<case>.nc.partial, so a failed
or killed run never spoils an earlier DIR/<case>.nc; a second run of the case into DIR at once
is refused (the lock DIR/.<case>.lock).

Exit codes: 0 done; 1 usage error; 2 the case is invalid (every problem on stderr as
FILE:LINE: what is wrong); 3 a step did not converge (the last converged state is written,
the diagnosis is on stderr); 4 the run failed otherwise (an output could not be written,
another run of the case is writing into DIR).

Examples:
  flexmoor run ex1-suspended-cable-8xL2
  flexmoor run -o runs/ex1 cases/seed/ex1-suspended-cable-8xL2.yaml --no-vtk
)";

inline constexpr const char* kCheckSummary = "check a case file without running it";

inline constexpr const char* kCheckDetails = R"(
Reads CASE and checks everything that can be known without solving: YAML syntax, keys and
their types, units and dimensions, value ranges, references to materials, sections, nodes,
lines, surfaces and histories, the geometry of the elements, the ocean (waves that would break,
nodes and bodies below the seabed), and the steps and summary.
A valid case prints one line (its nodes, elements, equations and steps) on stdout.

Exit codes: 0 the case is valid; 1 usage error; 2 the case is invalid: every problem is listed
on stderr, one a line, as FILE:LINE: what is wrong (got X, expected Y).

A study file (a YAML file with both case: and collect:, see 'flexmoor study --help') is checked
as a study: the file itself, then every member's case built and checked.

Examples:
  flexmoor check ex1-suspended-cable-8xL2
  flexmoor check cases/ocean/oc4-semi-surge.yaml
  flexmoor check oc4-semi-surg       # exit 2: no case 'oc4-semi-surg'; did you mean ...?
  flexmoor check cases/studies/tube-rao.yaml
)";

inline constexpr const char* kStudySummary =
    "run a study: one base case under many variations, in parallel or under mpirun";

inline constexpr const char* kStudyDetails = R"(
A study names a base case, the values to vary by their paths in it, and what to collect from
every member's run. An example (cases/studies/ has more):

  title: OC4 lines, JONSWAP seas, 3 seeds x 3 sea states
  case: oc4-jonswap-base.yaml        # the base case, relative to the study file
  grid:                              # every combination, the last path varying fastest
    waves.spectrum.Hs: [2 m, 4 m, 6 m]
    waves.seed: [1, 2, 3]
  # list: [{waves.spectrum.Hs: 2 m, waves.spectrum.Tp: 7 s}, ...]   members one by one,
  #   each crossed with the grid when both are given
  collect:
    - name: fairlead_tension_1       # a variable name in study.nc
      quantity: end_tension          # as a summary: entry: quantity, node, element, end, ...
      line: line_1                   # line_1's fairlead end (or element: 12, end: last)
      end: fairlead
      window: {from: 100 s}          # the part of the last dynamic step that counts
      statistics: [max, min, mean, std, amplitude, mpm]   # amplitude = (max - min) / 2
      mpm: {duration: 3 h, fit: weibull}   # most probable maximum: weibull (peaks) | gumbel
      spectrum: {segment: 100 s}     # Welch, Hann, half overlap; omitted: no spectrum

A path is the case's keys joined by '.', a list's index 0-based (waves.components.0.period);
it must be a value the base case gives. Before anything runs, the study and every member's case
are checked; problems are reported as STUDY:LINE (exit 2), naming the member.

DIR (-o) holds:
  DIR/study.nc                 one netCDF (CF-1.8) with a member dimension: the varied values
                               as coordinates (in the base case's units, each with its units),
                               status and error of each member, NAME_max,
                               NAME_min, NAME_mean, NAME_std (time-weighted over the window, as
                               a case's summary: statistics), NAME_amplitude, NAME_mpm (the
                               most probable maximum over mpm's duration, from a fit to the
                               series' peaks or block maxima), and NAME_psd on one
                               circular-frequency axis; a failed member's values are _FillValue
  DIR/members/NNNN/            member NNNN's run: <case>.nc, <case>.summary.json, series.nc
                               (the collected series over its window), run.log, errors.log,
                               and `complete` (a hash of the member's case text) or `failed`

Resuming: a rerun into the same DIR skips the members complete with the same case text; a
member whose values, base case or collect: changed, or that failed, runs again.

Parallel: the members run on -j N worker processes (default: the cores). Processes, not
threads: netCDF and HDF5 are not thread-safe, and a member that crashes or is killed takes down
only its worker; it is recorded as failed and the others carry on.

MPI: the same command under mpirun spreads the members over the ranks (member i to rank
(i - 1) mod K, each rank running its members one at a time); rank 0 writes study.nc when every
rank is done. DIR must be on a file system every rank sees. As root, OpenMPI needs
--allow-run-as-root; with more ranks than cores, --oversubscribe.

Exit codes: 0 every member complete; 1 usage error; 2 the study or a member's case is invalid
(nothing ran); 4 some member failed (study.nc says which and why).

Examples:
  flexmoor check cases/studies/tube-rao.yaml
  flexmoor study cases/studies/tube-rao.yaml -o results/tube-rao -j 2
  mpirun -n 2 flexmoor study cases/studies/oc4-jonswap.yaml -o results/oc4-jonswap
)";

inline constexpr const char* kCasesSummary = "list the named cases shipped under cases/";

inline constexpr const char* kCasesDetails = R"(
Prints one line per case under cases/: the name that 'flexmoor run NAME' and 'flexmoor check
NAME' accept, then its title. Takes no arguments.

Examples:
  flexmoor cases
)";

inline constexpr const char* kPlotSummary = "draw a figure of a run or a study as a PNG";

inline constexpr const char* kPlotDetails = R"(
Draws one figure from RESULT with the file's units, legends and title, using Debian's
matplotlib (/usr/bin/python3); forces in N are shown in kN or MN by their magnitude, ticks as
plain numbers, spectra up to where 99.9% of their energy lies (and a margin). One kind of
figure at a time:

Of a run (DIR/<case>.nc of 'flexmoor run'):
  --series SPEC ...  time series, one panel each (the default: the largest end tension and the
                     displacement of the node that moves most; the states closing the steps
                     that are not dynamic, the stage records, as points)
  --spectrum SPEC    the Welch spectrum (Hann window, half overlap, per rad/s) of one series
                     over the last step (records of time steps cut short interpolated onto the
                     step's dt), against the target spectrum of the run's sea (its
                     JONSWAP, Pierson-Moskowitz or table, and the synthesised band); the target
                     shares the axis when the series is a length, else has its own at the right.
                     --segment SECONDS (default: a quarter of the record), --from SECONDS (leave
                     out a start-up transient)
  --shapes T1,T2     the elements at the records nearest these times, one colour a time, in
                     --plane xz (or xy, yz), equal scales
  --mooring          every anchored line's fairlead tension over time, and the lines' profiles
                     (distance from the anchor against z) over the seabed and under the water
                     line (a spread mooring's figure when its case has no figure:)
SPEC is VARIABLE@INDEX with 1-based indices as in the file's coordinates:
  position_x@node=5            x of node 5 in the current configuration
  speed@node=5                 |velocity| of node 5
  tension_end@element=1,end=1  axial force at the first end of element 1 (end=first the same;
                               end=2 or end=last: the last), as the file's end coordinate
  wave_elevation               the sea's elevation at x = y = 0 (a variable of the record alone)

Of a study (DIR/study.nc of 'flexmoor study'; PARAMETER is a varied path with '.' as '_', as
listed in its study_parameters; failed members are left out):
  --rao NAME --against PARAMETER [--wave-height H|PARAMETER] [--group PARAMETER]
                     NAME_amplitude against the parameter; with --wave-height, divided by half
                     the wave height (a response-amplitude operator; a number H is in the
                     study's length unit, its unit_system's)
  --extremes NAME --against PARAMETER [--group PARAMETER]
                     NAME_max (filled markers) and NAME_mpm (open markers, when collected)
                     against the parameter, one colour per value of --group, and their means
                     over the group as lines
  --psd NAME         every member's response spectrum NAME_psd over the study's frequency axis

Bad arguments (a variable, parameter or time the file does not hold, an option of another
figure) are named on stderr, exit code 2. The directory of -o is created when it is not there.
Any other failure (the PNG cannot be written, a Python module is missing) is one line on stderr,
exit code 4.

Examples:
  flexmoor run driven-taut-cable     # results/driven-taut-cable/driven-taut-cable.nc
  flexmoor plot results/driven-taut-cable/driven-taut-cable.nc -o cable.png
  flexmoor plot results/driven-taut-cable/driven-taut-cable.nc -o tension.png \
      --series tension_end@element=1,end=first --series speed@node=5
  flexmoor run oc4-jonswap-base -o results     # a run in a sea: results/oc4-jonswap-base.nc
  flexmoor plot results/oc4-jonswap-base.nc -o sea.png --spectrum wave_elevation --from 100
  flexmoor plot results/oc4-jonswap-base.nc -o fairlead.png \
      --spectrum tension_end@element=1,end=1 --segment 200
  flexmoor plot results/oc4-jonswap-base.nc -o shapes.png --shapes 100,200,300
  flexmoor plot results/oc4-jonswap-base.nc -o mooring.png --mooring
  # the studies of 'flexmoor study --help' (tube-rao's waves are 5 ft high):
  flexmoor plot results/tube-rao/study.nc -o rao.png --rao heave \
      --against waves_components_0_period --wave-height 5
  flexmoor plot results/oc4-jonswap/study.nc -o extremes.png --extremes fairlead_tension_1 \
      --against waves_spectrum_Hs --group waves_seed
  flexmoor plot results/oc4-jonswap/study.nc -o psd.png --psd fairlead_tension_1
)";

}  // namespace flexmoor::cli
