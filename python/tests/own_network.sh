#!/bin/sh
# Runs PYTHON in a network namespace of its own whose only interface is loopback:
# python/run_tests.sh starts each pytest worker so. Tests count what a simulator executed, and
# within one namespace a client of one worker could reach another worker's simulator (a port
# one closed and the other bound next); across namespaces no socket meets another. Unprivileged
# namespaces need a user namespace too, in which the worker is uid 0: a test that expects a
# permission to be refused cannot rely on it there.
#   own_network.sh PYTHON [ARG...]
exec unshare --map-root-user --net sh -c 'ip link set lo up && exec "$@"' own_network "$@"
