/* flexmoor.h: the C interface of flexmoor, for a host program (a platform simulator, a
 * wave-energy code, a CFD solver, coupling glue) that drives mooring lines step by step.
 *
 * A simulation is an opaque handle made from a case (a YAML file, or its text). Every function
 * returns FLEXMOOR_OK (0) or an error code; the message of a handle's last error is
 * flexmoor_last_error(handle). No C++ exception and no exit() ever crosses this interface.
 * Separate handles share nothing and may be used from separate threads at once; one handle is
 * used by one thread at a time. A handle is a number, not a pointer to memory: a call with a
 * closed one returns FLEXMOOR_BAD_CALL.
 *
 * Life cycle:
 *   flexmoor_create(path, &h)            read and check the case (its errors: FLEXMOOR_BAD_INPUT)
 *   flexmoor_couple(h, "platform")       optional: the host drives that rigid body (or point)
 *   flexmoor_set_output(h, dir)          optional: write the results files into dir
 *   flexmoor_init(h, n, x, xd)           the coupled dofs' start; statics; the dynamic step starts
 *   flexmoor_step(h, n, x, xd, xdd, f, &t, dt)   as often as the host likes
 *   flexmoor_save / flexmoor_restore     optional, any time after init
 *   flexmoor_finish(h)                   closes the run, writes the results files
 *   flexmoor_close(h)                    always, even after an error
 *
 * Coupled dofs. A coupled body (flexmoor_couple: a spread mooring's `platform`, or a history of
 * type rigid_motion) has six, in this order: surge, sway, heave (the translation of its
 * reference point from where the case puts it at rest, in the case's length unit) and roll,
 * pitch, yaw (rad; the rotation R = Rz(yaw) Ry(pitch) Rx(roll)). A coupled point (a line's end:
 * "LINE.fairlead", "LINE.anchor", "LINE.start", "LINE.end", held in x, y and z by the case's
 * supports) has three: its position x, y, z in the case's frame and length unit, as MoorDyn's
 * coupled points; the host's motion replaces what the supports prescribed there. Velocities and
 * accelerations are their time derivatives. The dofs of what is coupled follow one another in
 * the order of the flexmoor_couple calls. The loads returned, six per body, are the force of the
 * lines on the body (x, y, z, the case's force unit) and its moment about the body's reference
 * point where the body is (x, y, z); three per point, the force of the lines on the point.
 *
 * A step's semantics. flexmoor_step(h, n, x, xd, xdd, f, &t, dt) takes the simulation from time t
 * (the time it has reached) to t + dt. x, xd (and xdd, when not NULL) are the coupled dofs'
 * states AT THE END of the step, t + dt. Over the step the coupled dofs move on the Hermite
 * interpolant between their states at t (as the previous call, or flexmoor_init, gave them) and
 * at t + dt: quintic when accelerations are given at both ends, cubic in positions and
 * velocities otherwise. The lines are integrated implicitly (Newmark/HHT) in the case's own
 * time steps or shorter, the last one landing on t + dt exactly; f receives the loads AT t + dt,
 * from the converged state there. A step that fails (the lines' Newton iterations do not
 * converge, an absurd motion) returns FLEXMOOR_NOT_CONVERGED with the simulation left at its
 * last converged time (flexmoor_time); restore a checkpoint and try again, or finish.
 */
#ifndef FLEXMOOR_H
#define FLEXMOOR_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct flexmoor_simulation* flexmoor_t;
typedef struct flexmoor_checkpoint* flexmoor_checkpoint_t;

/* The error codes; BAD_INPUT, NOT_CONVERGED and FAILED are those of the flexmoor command's exits. */
enum flexmoor_status {
  FLEXMOOR_OK = 0,
  FLEXMOOR_BAD_CALL = 1,      /* a call out of order, a null or closed handle, a wrong argument */
  FLEXMOOR_BAD_INPUT = 2,     /* the case has errors (each FILE:LINE: what is wrong) */
  FLEXMOOR_NOT_CONVERGED = 3, /* a step did not converge; the last converged state is kept */
  FLEXMOOR_FAILED = 4         /* anything else: a file that cannot be written, out of memory */
};

/* The library's version, "MAJOR.MINOR.PATCH". */
const char* flexmoor_version(void);

/* A simulation of the case in the YAML file at `path` (a named case's name also: as `flexmoor
 * run NAME` finds it). *handle is set even when this fails (unless memory ran out: NULL), so that
 * flexmoor_last_error tells why; close it in every case. */
int flexmoor_create(const char* path, flexmoor_t* handle);
/* The same from the case's text; `name` is its name in messages and results files. */
int flexmoor_create_from_yaml(const char* yaml, const char* name, flexmoor_t* handle);
/* Ends the simulation (without writing results files unless flexmoor_finish did) and frees the
 * handle; NULL is accepted. */
void flexmoor_close(flexmoor_t handle);
/* The message of the handle's last error, "" when the last call succeeded; valid until the
 * next call on the handle. For a NULL handle, a fixed message. */
const char* flexmoor_last_error(flexmoor_t handle);

/* Where progress (level 0) and diagnoses (level 1) go, one line per call (no newline); by default
 * nowhere. Before flexmoor_init. */
typedef void (*flexmoor_log_function)(void* user_data, int level, const char* line);
int flexmoor_set_logger(flexmoor_t handle, flexmoor_log_function log, void* user_data);
/* The results files (netCDF, summary, VTK) go into `directory` (created if needed), written by
 * flexmoor_finish as `flexmoor run -o DIRECTORY` writes them; by default none. Before init. */
int flexmoor_set_output(flexmoor_t handle, const char* directory);

/* The host drives rigid body or point `name` (its six or three dofs above), in the order of the
 * calls; before init. A point a coupled body carries cannot be coupled too. */
int flexmoor_couple(flexmoor_t handle, const char* name);
/* The number of coupled dofs: 6 per coupled body. */
int flexmoor_coupled_dofs(flexmoor_t handle, int* count);

/* The coupled dofs at rest in x with velocities xd (count values each, which must be
 * flexmoor_coupled_dofs; NULL when there are none) at the case's start time; runs the steps before
 * the case's dynamic step (its statics) and starts it. */
int flexmoor_init(flexmoor_t handle, int count, const double* x, const double* xd);
/* One step of the host, from *t to *t + dt (see the header comment); *t must be the time reached
 * and is set to the step's end on success. count as for flexmoor_init; xdd and f may be NULL.
 * A host that steps at a constant dt reaches t0 + n dt computed, not summed, so that its times
 * and the results' are on its grid to the last bit. */
int flexmoor_step(flexmoor_t handle, int count, const double* x, const double* xd,
                  const double* xdd, double* f, double* t, double dt);
/* The time reached. */
int flexmoor_time(flexmoor_t handle, double* t);
/* The loads on the coupled bodies now (as flexmoor_step returns them). */
int flexmoor_coupled_loads(flexmoor_t handle, double* f);

/* The named lines (the case's `lines:`, a spread mooring's line_1, line_2, ...). Index `line`
 * counts from 0 in the case's order; `name` stays valid while the handle is open. */
int flexmoor_line_count(flexmoor_t handle, int* count);
int flexmoor_line_name(flexmoor_t handle, int line, const char** name);
int flexmoor_line_node_count(flexmoor_t handle, int line, int* count);
/* Node `node` of the line (0 at its start) now: position (x, y, z) and velocity. */
int flexmoor_line_node_position(flexmoor_t handle, int line, int node, double position[3]);
int flexmoor_line_node_velocity(flexmoor_t handle, int line, int node, double velocity[3]);
/* The tension at the line's start (end 0) or end (end 1) now, from the nodal force balance of
 * the element there (the case's force unit). */
int flexmoor_line_end_tension(flexmoor_t handle, int line, int end, double* tension);

/* The whole state: every node's position, 3 values each (the model's node order). */
int flexmoor_node_count(flexmoor_t handle, int* count);
int flexmoor_node_positions(flexmoor_t handle, double* positions);

/* A checkpoint of everything the simulation needs to go on from now, taken after init: going on
 * from it after flexmoor_restore is going on from the save, to the bit. While a checkpoint lives,
 * the results records after its time are held back from the results file, so that a restore can
 * take them back; free checkpoints no longer needed. */
int flexmoor_save(flexmoor_t handle, flexmoor_checkpoint_t* checkpoint);
int flexmoor_restore(flexmoor_t handle, flexmoor_checkpoint_t checkpoint);
void flexmoor_checkpoint_free(flexmoor_checkpoint_t checkpoint);
/* The same in a file, to go on in another process: flexmoor_restore_file needs a handle of the
 * same case, its same bodies coupled, after init. Records after the file's time that the handle
 * has written already cannot be taken back: restoring to before them is refused. */
int flexmoor_save_file(flexmoor_t handle, const char* path);
int flexmoor_restore_file(flexmoor_t handle, const char* path);

/* Runs the whole case as `flexmoor run` does (every step in its own time steps, the prescribed
 * motions its own: no body may be coupled), instead of init, steps and finish. */
int flexmoor_run(flexmoor_t handle);

/* Closes the dynamic step, runs the case's steps after it, evaluates its summary and writes the
 * results files (flexmoor_set_output). FLEXMOOR_NOT_CONVERGED when a later step does not
 * converge (its last converged state written). */
int flexmoor_finish(flexmoor_t handle);
/* The summary the case declares, after finish or run: `index` from 0. */
int flexmoor_summary_count(flexmoor_t handle, int* count);
int flexmoor_summary_value(flexmoor_t handle, int index, const char** name, double* value);

#ifdef __cplusplus
}
#endif

#endif /* FLEXMOOR_H */
