"""An IFC2x3 file nested N levels deep: the FZK-Haus (AC14, assimp-testmodels)
with a chain of N building element proxies, each aggregated by the one before,
the first by the building (#580). Usage: ifc_nested.py FZK.ifc OUT.ifc N"""
import sys

source, output, levels = sys.argv[1], sys.argv[2], int(sys.argv[3])
text = open(source, encoding="latin-1").read()
end = text.rindex("ENDSEC;")  # the DATA section's
lines, parent = [], 580
for k in range(levels):
    proxy = 900000 + 2 * k
    lines.append(f"#{proxy}= IFCBUILDINGELEMENTPROXY('{k:022d}',#13,'p{k}',$,$,$,$,$,$);")
    lines.append(f"#{proxy + 1}= IFCRELAGGREGATES('{k + 10**21:022d}',#13,$,$,#{parent},(#{proxy}));")
    parent = proxy
open(output, "w", encoding="latin-1").write(text[:end] + "\n".join(lines) + "\n" + text[end:])
