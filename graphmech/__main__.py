import sys

from graphmech.cli import main

sys.exit(main())
