"""python -m taucli"""

import sys

from taucli.cli import main

sys.exit(main())
