/* cc_demo: a headless demo of circlecollide that writes PPM frames. Parses the command line and
 * hands over to demo_run; exit codes: 0 done, 1 run failed, 2 bad command line. */
#include "args.h"
#include "run.h"

#include <stdio.h>

int main(int argc, char **argv)
{
    demo_options o;
    char err[256];
    int r = demo_parse_args(argc, argv, &o, err, sizeof err);
    if (r == DEMO_ARGS_HELP) {
        demo_print_usage(stdout);
        return 0;
    }
    if (r != DEMO_ARGS_RUN) {
        fprintf(stderr, "cc_demo: %s\nRun 'cc_demo --help' for the options.\n", err);
        return DEMO_ARGS_ERROR;
    }
    return demo_run(&o);
}
