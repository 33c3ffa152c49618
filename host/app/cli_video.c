/* Encoding a sequence with ffmpeg, run without a shell (posix_spawnp). */
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_common.h"
#include "cli_video.h"

extern char **environ;

/* 1 when `name` is an executable file in a directory of $PATH. */
static int on_path(const char *name) {
    const char *path = getenv("PATH");
    char dir[4096], file[4352];
    for (const char *p = path; p && *p;) {
        const char *colon = strchr(p, ':');
        const size_t n = colon ? (size_t)(colon - p) : strlen(p);
        snprintf(dir, sizeof dir, "%.*s", (int)n, p);
        snprintf(file, sizeof file, "%s/%s", dir[0] ? dir : ".", name);
        if (access(file, X_OK) == 0)
            return 1;
        p = colon ? colon + 1 : p + n;
    }
    return 0;
}

static int ends_with(const char *s, const char *end) {
    const size_t a = strlen(s), b = strlen(end);
    return a >= b && strcmp(s + a - b, end) == 0;
}

int cli_video_check(const cli_options *opt, const char *pattern, vct_error *err) {
    if (!opt->video)
        return VCT_OK;
    if (opt->frames[1] < 0)
        return cli_fail_input(err, "vct render --video encodes a sequence: give --frames A:B");
    if (!ends_with(pattern, ".png") && !ends_with(pattern, ".exr"))
        return cli_fail_input(err,
                              "vct render --video: ffmpeg reads the frames as PNG or EXR, not %s: "
                              "name them out/shot_%%04d.png",
                              pattern);
    if (!strrchr(opt->video, '.'))
        return cli_fail_input(err,
                              "vct render --video %s: give the file an ending (.mp4, .webm, "
                              ".gif): ffmpeg picks the format from it",
                              opt->video);
    if (!on_path("ffmpeg"))
        return cli_fail_input(err, "vct render --video: ffmpeg is not installed (on Debian: "
                                   "apt install ffmpeg); render the frames without --video");
    return VCT_OK;
}

int cli_video_make(const cli_options *opt, const char *pattern, vct_error *err) {
    if (!opt->video)
        return VCT_OK;
    /* NAME.partial.EXT while ffmpeg writes: it picks the format by the ending */
    const char *dot = strrchr(opt->video, '.');
    char partial[2048], rate[32], first[32];
    snprintf(partial, sizeof partial, "%.*s.partial%s", (int)(dot - opt->video), opt->video, dot);
    snprintf(rate, sizeof rate, "%g", opt->fps);
    snprintf(first, sizeof first, "%d", opt->frames[0]);
    char count[32];
    snprintf(count, sizeof count, "%d", opt->frames[1] - opt->frames[0] + 1);
    char *argv[20];
    int n = 0;
    char *fixed[] = {"ffmpeg",        "-y",  "-loglevel", "error",         "-framerate", rate,
                     "-start_number", first, "-i",        (char *)pattern, "-frames:v",  count};
    for (size_t k = 0; k < sizeof fixed / sizeof *fixed; ++k)
        argv[n++] = fixed[k];
    if (ends_with(opt->video, ".mp4") || ends_with(opt->video, ".mov")) {
        argv[n++] = "-pix_fmt"; /* what players read */
        argv[n++] = "yuv420p";
    }
    argv[n++] = partial;
    argv[n] = NULL;
    if (cli_make_parent_dir(opt->video, err) != VCT_OK)
        return err->status;
    pid_t pid;
    int status = 0;
    if (posix_spawnp(&pid, "ffmpeg", NULL, NULL, argv, environ) != 0 ||
        waitpid(pid, &status, 0) != pid)
        return cli_fail_input(err, "vct render --video: could not run ffmpeg");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        remove(partial);
        return cli_fail_input(err,
                              "vct render --video: ffmpeg failed (status %d) on %s; the frames "
                              "are written",
                              WIFEXITED(status) ? WEXITSTATUS(status) : -1, pattern);
    }
    if (rename(partial, opt->video) != 0) {
        remove(partial);
        return cli_fail_input(err, "vct render --video: could not write %s", opt->video);
    }
    fprintf(stderr, "wrote %s (%d frames at %s fps, ffmpeg)\n", opt->video,
            opt->frames[1] - opt->frames[0] + 1, rate);
    return VCT_OK;
}
