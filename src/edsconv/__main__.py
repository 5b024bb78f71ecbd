from edsconv.cli import main

main()
