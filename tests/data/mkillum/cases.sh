# The mkillum cases of tests/golden/mkillum.sh and make_refs.sh (sourced): one line
# each, name|render options|input|the files it writes besides standard output.
# shellcheck disable=SC2034
mkillum_cases='windows|-ab 0|windows.rad|win.dat win1.dat shadeR.dat shadeG.dat shadeB.dat
sunlit|-ab 1 -aa 0 -ad 64 -lw 1e-3|sunlit.rad|sunlitR.dat sunlitG.dat sunlitB.dat
misc|-ab 0|misc.rad|named.dat named1.dat named2.dat named3.dat named4.dat named5.dat named6.dat last.dat rest.rad'
