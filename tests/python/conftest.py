"""pytest set-up of Sinew's Python tests: the package from python/ of the source tree, the sinew
executable from $SINEW_BIN (ctest sets both), Open MPI as the system tests run it."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "python"))
os.environ.setdefault("SINEW_BIN", os.path.join(SOURCE, "build", "sinew"))
for k, v in (("OMPI_ALLOW_RUN_AS_ROOT", "1"), ("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1"),
             ("OMPI_MCA_rmaps_base_oversubscribe", "1"), ("OMPI_MCA_pml", "ob1"), ("OMPI_MCA_btl", "self,vader")):
    os.environ.setdefault(k, v)
