#include "solver.h"

#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "checkpoint.h"
#include "scene_ini.h"
#include "table.h"

#define MAX_WORDS 64
#define SPLIT_BYTES 4096   /* the words of a command, NUL-separated */

int vfy_solver_split(const char *command, char **words, size_t max, char *buf, size_t bufsize,
                     char *msg, size_t msglen)
{
    size_t n = 0, used = 0;
    const char *p = command;
    for (;;) {
        while (*p == ' ' || *p == '\t' || *p == '\n')
            p++;
        if (*p == '\0')
            break;
        if (n == max) {
            snprintf(msg, msglen, "more than %zu words", max);
            return -1;
        }
        words[n++] = buf + used;
        char quote = 0;
        for (; *p != '\0' && (quote || (*p != ' ' && *p != '\t' && *p != '\n')); p++) {
            char c = *p;
            if (quote == 0 && (c == '\'' || c == '"')) {
                quote = c;
                continue;
            }
            if (c == quote) {
                quote = 0;
                continue;
            }
            if (quote == '"' && c == '\\' && (p[1] == '"' || p[1] == '\\'))
                c = *++p;
            if (used + 2 > bufsize) {
                snprintf(msg, msglen, "longer than %zu characters", bufsize - 2);
                return -1;
            }
            buf[used++] = c;
        }
        if (quote) {
            snprintf(msg, msglen, "an unterminated %s quote", quote == '"' ? "double" : "single");
            return -1;
        }
        buf[used++] = '\0';
    }
    if (n == 0)
        snprintf(msg, msglen, "no command");
    return n ? (int)n : -1;
}

/* h updated with the contents of the regular file at path (unchanged if it
 * is not one). */
static uint64_t hash_file(uint64_t h, const char *path)
{
    struct stat st;
    FILE *f = stat(path, &st) == 0 && S_ISREG(st.st_mode) ? fopen(path, "rb") : NULL;
    if (f == NULL)
        return h;
    char buf[65536];
    for (size_t got; (got = fread(buf, 1, sizeof buf, f)) > 0;)
        h = vfy_hash(h, buf, got);
    fclose(f);
    return h;
}

uint64_t vfy_solver_identity(const char *command)
{
    uint64_t h = vfy_hash(VFY_HASH_START, command, strlen(command));
    char *words[MAX_WORDS], buf[SPLIT_BYTES], why[64];
    const int n = vfy_solver_split(command, words, MAX_WORDS, buf, sizeof buf, why, sizeof why);
    for (int k = 0; k < n; k++) {
        if (k > 0 || strchr(words[k], '/') != NULL) {
            h = hash_file(h, words[k]);
            continue;
        }
        const char *path = getenv("PATH");   /* the program, as execvp finds it */
        for (const char *dir = path; dir && *dir;) {
            const size_t len = strcspn(dir, ":");
            char full[1100];
            snprintf(full, sizeof full, "%.*s/%s", (int)len, dir, words[k]);
            if (access(full, X_OK) == 0) {
                h = hash_file(h, full);
                break;
            }
            dir += len + (dir[len] == ':');
        }
    }
    return h;
}

/* Whether some word holds the placeholder ph ("{scene}"); -1 when a word
 * holds its start without the closing brace ("{out" or "{out/x"). */
static int has_placeholder(char *const *words, int n, const char *ph)
{
    int found = 0;
    const size_t stem = strlen(ph) - 1;   /* without the '}' */
    for (int k = 0; k < n; k++)
        found |= strstr(words[k], ph) != NULL;
    for (int k = 0; k < n; k++)
        for (const char *p = words[k]; (p = strchr(p, '{')) != NULL; p++)
            if (strncmp(p, ph, stem) == 0 && p[stem] != '}')
                return -1;
    return found;
}

int vfy_solver_command_ok(const char *command, char *msg, size_t msglen)
{
    char *words[MAX_WORDS], buf[SPLIT_BYTES];
    const int n = vfy_solver_split(command, words, MAX_WORDS, buf, sizeof buf, msg, msglen);
    if (n <= 0)
        return 0;
    static const char *const placeholders[] = {"{scene}", "{out}"};
    for (size_t i = 0; i < 2; i++) {
        const int has = has_placeholder(words, n, placeholders[i]);
        if (has < 0) {
            snprintf(msg, msglen, "an unterminated placeholder '%.*s' (write %s)",
                     (int)strlen(placeholders[i]) - 1, placeholders[i], placeholders[i]);
            return 0;
        }
        if (has == 0) {
            snprintf(msg, msglen, "no %s: the command must name where %s", placeholders[i],
                     i == 0 ? "the scene file is ({scene})" : "the result goes ({out})");
            return 0;
        }
    }
    return 1;
}

/* word with every {scene} and {out} replaced, in dst; -1 if it does not fit. */
static int substitute(const char *word, const char *scene, const char *out, char *dst,
                      size_t cap)
{
    size_t used = 0;
    while (*word) {
        const char *with = NULL;
        size_t skip = 1;
        if (strncmp(word, "{scene}", 7) == 0)
            with = scene, skip = 7;
        else if (strncmp(word, "{out}", 5) == 0)
            with = out, skip = 5;
        size_t len = with ? strlen(with) : 1;
        if (used + len + 1 > cap)
            return -1;
        memcpy(dst + used, with ? with : word, len);
        used += len;
        word += skip;
    }
    dst[used] = '\0';
    return 0;
}

/* The last bytes of the file at path (at most cap - 1) in text,
 * NUL-terminated, trailing white space removed; *cut whether the file held
 * more.  Returns their length (0 when the file cannot be read). */
static size_t read_tail(const char *path, char *text, size_t cap, int *cut)
{
    text[0] = '\0';
    *cut = 0;
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return 0;
    fseek(f, 0, SEEK_END);
    const long size = ftell(f), want = (long)cap - 1;
    *cut = size > want;
    fseek(f, *cut ? size - want : 0, SEEK_SET);
    size_t len = fread(text, 1, (size_t)want, f);
    fclose(f);
    text[len] = '\0';
    while (len > 0 && strchr(" \t\r\n", text[len - 1]) != NULL)
        text[--len] = '\0';
    return len;
}

/* The last lines of the log (at most about 600 characters), indented. */
static void log_tail(const char *path, char *buf, size_t cap)
{
    char text[601];
    int cut;
    const size_t len = read_tail(path, text, sizeof text, &cut);
    buf[0] = '\0';
    const char *start = text;
    int lines = 0;
    for (size_t i = len; i-- > 0;)
        if (text[i] == '\n' && ++lines == 5) {
            start = text + i + 1;
            break;
        }
    if (cut && start == text) {   /* a cut first line */
        const char *nl = strchr(text, '\n');
        start = nl ? nl + 1 : text;
    }
    size_t used = 0;
    for (const char *p = start; *p && used + 8 < cap; p++) {
        if (p == start || p[-1] == '\n')
            used += (size_t)snprintf(buf + used, cap - used, "\n    ");
        if (*p != '\n' && used + 1 < cap)
            buf[used++] = *p;
    }
    buf[used < cap ? used : cap - 1] = '\0';
}

/* The last non-blank line of the file at path (at most cap - 1 bytes of it,
 * trailing white space removed) in buf; "" when there is none. */
static void last_line(const char *path, char *buf, size_t cap)
{
    char text[1025];
    int cut;
    read_tail(path, text, sizeof text, &cut);
    const char *nl = strrchr(text, '\n'), *line = nl ? nl + 1 : text;
    const size_t n = strlen(line) < cap - 1 ? strlen(line) : cap - 1;
    memcpy(buf, line, n);
    buf[n] = '\0';
}

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Start argv with its standard output to log and its standard error to err:
 * the child's pid, or -1 with errno set (the exec's own errno when the
 * command could not be run). */
static pid_t start(char **argv, const char *log, const char *err)
{
    int fds[2];
    if (pipe(fds) != 0)
        return -1;
    fcntl(fds[1], F_SETFD, FD_CLOEXEC);
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return -1;
    }
    if (pid == 0) {   /* the child: its own process group, output to the log */
        close(fds[0]);
        setpgid(0, 0);
        int in = open("/dev/null", O_RDONLY);
        int out = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int errs = open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in >= 0)
            dup2(in, 0);
        if (out >= 0)
            dup2(out, 1);
        if (errs >= 0)
            dup2(errs, 2);
        execvp(argv[0], argv);
        int e = errno;
        ssize_t ignored = write(fds[1], &e, sizeof e);
        (void)ignored;
        _exit(127);
    }
    close(fds[1]);
    int e = 0;
    ssize_t got = read(fds[0], &e, sizeof e);   /* 0 bytes: the exec happened */
    close(fds[0]);
    if (got == (ssize_t)sizeof e) {
        waitpid(pid, NULL, 0);
        errno = e;
        return -1;
    }
    return pid;
}

/* The solver's command as an argv: its words, with the scene's and the
 * result's paths put in (substitute), pointing into buf and expanded. */
typedef struct solver_argv {
    char *words[MAX_WORDS + 1], buf[SPLIT_BYTES], expanded[MAX_WORDS][1200];
} solver_argv;

/* Split the solver's command into av with scene_path and out_path put in:
 * SIM_OK, or SIM_EINVAL with msg (the command is bad, or a word too long). */
static sim_status command_argv(const vfy_solver *solver, const char *scene_path,
                               const char *out_path, solver_argv *av, char *msg, size_t msglen)
{
    char why[200];
    int n = vfy_solver_split(solver->command, av->words, MAX_WORDS, av->buf, sizeof av->buf, why,
                             sizeof why);
    if (n < 0) {
        snprintf(msg, msglen, "--solver '%s': %s", solver->command, why);
        return SIM_EINVAL;
    }
    for (int k = 0; k < n; k++) {
        if (substitute(av->words[k], scene_path, out_path, av->expanded[k],
                       sizeof av->expanded[k]) != 0) {
            snprintf(msg, msglen, "--solver '%s': word %d is too long with the paths in it",
                     solver->command, k + 1);
            return SIM_EINVAL;
        }
        av->words[k] = av->expanded[k];
    }
    av->words[n] = NULL;
    return SIM_OK;
}

/* Wait for the solver started as pid at wall0 (polling, the pause doubling
 * up to 50 ms): SIM_OK with its wait status and resource use; killed (its
 * process group) on a stop request (SIM_ECANCELED), past the timeout or when
 * waiting fails (SIM_EINVAL), with msg. */
static sim_status await_solver(const vfy_solver *solver, const char *label, pid_t pid,
                               double wall0, int *status, struct rusage *ru, char *msg,
                               size_t msglen)
{
    double pause = 1e-3;
    for (;;) {
        pid_t done = wait4(pid, status, WNOHANG, ru);
        if (done == pid)
            return SIM_OK;
        const int stop = sim_ensemble_stop_requested();
        const int late = wall_now() - wall0 > solver->timeout;
        if (stop || late || done < 0) {
            kill(-pid, SIGKILL);
            wait4(pid, status, 0, ru);
            if (stop) {
                snprintf(msg, msglen, "%s: stopped (the solver killed)", label);
                return SIM_ECANCELED;
            }
            snprintf(msg, msglen, "%s: the solver took more than %g s (--solver-timeout) and was "
                     "killed (--solver '%s')", label, solver->timeout, solver->command);
            return SIM_EINVAL;
        }
        struct timespec ts = {0, (long)(pause * 1e9)};
        nanosleep(&ts, NULL);
        pause = fmin(2.0 * pause, 0.05);
    }
}

/* How the solver ended (its wait status): SIM_OK when it exited with 0;
 * SIM_EUNSUPPORTED with its reason (the last line of err_path) as msg when
 * it refused; otherwise SIM_EINVAL with msg quoting the last lines of its
 * standard error (or of its output log_path when that is empty). */
static sim_status solver_exit_status(const vfy_solver *solver, const char *label, int status,
                                     const char *log_path, const char *err_path, char *msg,
                                     size_t msglen)
{
    char tail[700], why[200];
    if (WIFEXITED(status) && WEXITSTATUS(status) == VFY_SOLVER_REFUSES) {
        last_line(err_path, tail, 240);
        if (tail[0] != '\0') {   /* a refusal: the reason is the message */
            snprintf(msg, msglen, "%s", tail);
            return SIM_EUNSUPPORTED;
        }
        snprintf(msg, msglen, "%s: the solver exited with status %d, a refusal, but gave no "
                 "reason as the last line of its standard error %s (--solver '%s')", label,
                 VFY_SOLVER_REFUSES, err_path, solver->command);
        return SIM_EINVAL;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        struct stat es;   /* the standard error, or the output when that is empty */
        const char *quoted = stat(err_path, &es) == 0 && es.st_size > 0 ? err_path : log_path;
        log_tail(quoted, tail, sizeof tail);
        if (WIFSIGNALED(status))
            snprintf(why, sizeof why, "was killed by signal %d (%s)", WTERMSIG(status),
                     strsignal(WTERMSIG(status)));
        else
            snprintf(why, sizeof why, "exited with status %d", WEXITSTATUS(status));
        snprintf(msg, msglen, "%s: the solver %s (--solver '%s'); the last lines of its output "
                 "(%s):%s", label, why, solver->command, quoted,
                 tail[0] ? tail : "\n    (none)");
        return SIM_EINVAL;
    }
    return SIM_OK;
}

sim_status vfy_solver_run(const vfy_solver *solver, const sim_scene *scene, const char *label,
                          sim_ensemble_result *res, vfy_result_info *info, char *msg,
                          size_t msglen)
{
    memset(res, 0, sizeof *res);
    memset(info, 0, sizeof *info);
    char scene_path[1100], out_path[1100], log_path[1100], err_path[1100];
    const uint64_t key = vfy_checkpoint_key(scene);
    snprintf(scene_path, sizeof scene_path, "%s/%016" PRIx64 ".ini", solver->work_dir, key);
    snprintf(out_path, sizeof out_path, "%s/%016" PRIx64 ".result", solver->work_dir, key);
    snprintf(log_path, sizeof log_path, "%s/%016" PRIx64 ".log", solver->work_dir, key);
    snprintf(err_path, sizeof err_path, "%s/%016" PRIx64 ".err", solver->work_dir, key);

    solver_argv av;
    sim_status rc = command_argv(solver, scene_path, out_path, &av, msg, msglen);
    if (rc != SIM_OK)
        return rc;

    FILE *f = vfy_ensure_dir(solver->work_dir) == 0 ? fopen(scene_path, "w") : NULL;
    int written = f != NULL && vfy_scene_write(f, scene) == 0;
    if (f == NULL || fclose(f) != 0 || !written) {
        snprintf(msg, msglen, "%s: cannot write: %s", scene_path, strerror(errno));
        return SIM_EIO;
    }
    unlink(out_path);   /* a result from before must not pass for this run's */

    const double wall0 = wall_now();
    pid_t pid = start(av.words, log_path, err_path);
    if (pid < 0) {
        snprintf(msg, msglen, "%s: the solver cannot be started: '%s': %s (--solver '%s')",
                 label, av.words[0], strerror(errno), solver->command);
        return SIM_EINVAL;
    }
    int status = 0;
    struct rusage ru;
    if ((rc = await_solver(solver, label, pid, wall0, &status, &ru, msg, msglen)) != SIM_OK)
        return rc;
    const double wall = wall_now() - wall0;
    rc = solver_exit_status(solver, label, status, log_path, err_path, msg, msglen);
    if (rc != SIM_OK)
        return rc;
    struct stat st;
    if (stat(out_path, &st) != 0) {
        snprintf(msg, msglen, "%s: the solver exited with status 0 but wrote no result %s "
                 "(--solver '%s')", label, out_path, solver->command);
        return SIM_EINVAL;
    }
    sim_status read = vfy_result_read(out_path, scene, res, info, msg, msglen);
    if (read != SIM_OK)
        return read == SIM_EIO ? SIM_EINVAL : read;
    if (!info->has_cpu)
        res->cpu_seconds = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec
                           + (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
    res->wall_seconds = wall;
    return SIM_OK;
}
