"""Python-Markdown extension for the FORD API reference (doc/ford.md, tools/ford.sh).

The doc comments name the dimensionless quantities a*, c*, P*, p*, so an asterisk is part
of a name, never emphasis: this extension removes Markdown's asterisk emphasis (`*x*`,
`**x**`); underscores and code spans work as usual. Without it, "a* < c* < 1/2" would
render as "a<em> < c</em> < 1/2".
"""
from markdown.extensions import Extension


class NoAsteriskEmphasis(Extension):
    def extendMarkdown(self, md):
        if "em_strong" in md.inlinePatterns:
            md.inlinePatterns.deregister("em_strong")


def makeExtension(**kwargs):
    return NoAsteriskEmphasis(**kwargs)
