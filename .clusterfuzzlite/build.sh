#!/bin/bash -eu
# ClusterFuzzLite runs this; the build itself is the OSS-Fuzz one.
exec "$SRC/rotorcert/fuzz/oss-fuzz/build.sh"
