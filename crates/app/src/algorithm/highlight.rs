//! Syntax colouring of algorithm source, from the language's own lexer, so
//! the view and the compiler never disagree about what a word is.

use crate::visuals::CODE_BOLD_FAMILY;
use edgewise_core::schema::Structure;
use std::ops::Range;

use edgewise_core::lang::{
    Type,
    lexer::tokenize,
    token::{Token, TokenKind},
};
use egui::{Color32, FontId, TextFormat, text::LayoutJob};

/// How a piece of source is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    Plain,
    Keyword,
    /// `Vertex`, `Edge`, `Face`, `Integer`, `Boolean`, `WingedEdge`, `HalfEdge`.
    TypeName,
    Number,
    Text,
    Comment,
}

/// The source split into classified byte ranges covering all of it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Highlighted {
    pub segments: Vec<(Range<usize>, Class)>,
}

impl Highlighted {
    pub fn new(source: &str) -> Self {
        let (tokens, _) = tokenize(source);
        let mut segments = Vec::with_capacity(tokens.len() * 2);
        let mut at = 0;
        for Token { kind, span } in tokens {
            let range = span.range();
            if range.start > at {
                gap(source, at..range.start, &mut segments);
            }
            if range.is_empty() {
                continue;
            }
            let word = source.get(range.clone()).unwrap_or("");
            let class = match kind {
                TokenKind::Ident
                    if Type::parse(word).is_some() || Structure::parse(word).is_some() =>
                {
                    Class::TypeName
                }
                TokenKind::Ident => Class::Plain,
                TokenKind::Integer => Class::Number,
                TokenKind::String => Class::Text,
                kind if kind.is_keyword() => Class::Keyword,
                _ => Class::Plain,
            };
            at = range.end;
            segments.push((range, class));
        }
        if at < source.len() {
            gap(source, at..source.len(), &mut segments);
        }
        Self { segments }
    }

    /// A layout of `range` of `source` (a line, or the whole text), with
    /// each mark's bytes restyled: the expression being executed on a
    /// coloured background, or an error underlined.
    pub fn layout(
        &self,
        source: &str,
        range: Range<usize>,
        marks: &[Mark],
        style: &CodeStyle,
    ) -> LayoutJob {
        let mut job = LayoutJob::default();
        let first = self.segments.partition_point(|(r, _)| r.end <= range.start);
        for (segment, class) in self.segments.get(first..).unwrap_or(&[]) {
            if segment.start >= range.end {
                break;
            }
            let start = segment.start.max(range.start);
            let end = segment.end.min(range.end);
            // Split where marks start and end.
            let mut cuts = vec![start, end];
            for mark in marks {
                cuts.extend(
                    [mark.range.start, mark.range.end]
                        .into_iter()
                        .filter(|&c| c > start && c < end),
                );
            }
            cuts.sort_unstable();
            cuts.dedup();
            for pair in cuts.windows(2) {
                let (a, b) = (pair[0], pair[1]);
                let Some(text) = source.get(a..b) else {
                    continue;
                };
                let mut format = style.format(*class);
                // An empty mark (an error at the end of a line) still marks
                // the character it stands on.
                let covers =
                    |m: &&Mark| a >= m.range.start && b <= m.range.end.max(m.range.start + 1);
                if let Some(mark) = marks.iter().find(covers) {
                    format.background = mark.background;
                    if let Some(colour) = mark.text {
                        format.color = colour;
                    }
                    format.underline = mark.underline;
                }
                job.append(text, 0.0, format);
            }
        }
        job
    }
}

/// A restyled stretch of code.
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    pub range: Range<usize>,
    pub background: Color32,
    /// Replaces the syntax colour, for contrast on the background.
    pub text: Option<Color32>,
    pub underline: egui::Stroke,
}

/// Comments inside a stretch between tokens (whitespace otherwise).
fn gap(source: &str, range: Range<usize>, segments: &mut Vec<(Range<usize>, Class)>) {
    let text = source.get(range.clone()).unwrap_or("");
    let mut at = range.start;
    let mut rest = text;
    while let Some(i) = rest.find("//") {
        let comment_start = at + i;
        let comment_len = rest[i..].find('\n').unwrap_or(rest.len() - i);
        if comment_start > at {
            segments.push((at..comment_start, Class::Plain));
        }
        segments.push((comment_start..comment_start + comment_len, Class::Comment));
        at = comment_start + comment_len;
        rest = source.get(at..range.end).unwrap_or("");
    }
    if at < range.end {
        segments.push((at..range.end, Class::Plain));
    }
}

/// Fonts and colours for code.
#[derive(Clone, Debug)]
pub struct CodeStyle {
    pub font: FontId,
    pub text: Color32,
    pub keyword: Color32,
    pub type_name: Color32,
    pub number: Color32,
    pub string: Color32,
    pub comment: Color32,
    pub emphasis_text: Color32,
}

impl CodeStyle {
    pub fn new(font_size: f32, dark: bool) -> Self {
        let font = FontId::monospace(font_size);
        if dark {
            Self {
                font,
                text: Color32::from_rgb(220, 220, 224),
                keyword: Color32::from_rgb(255, 255, 255),
                type_name: Color32::from_rgb(130, 200, 230),
                number: Color32::from_rgb(230, 170, 120),
                string: Color32::from_rgb(170, 210, 140),
                comment: Color32::from_rgb(140, 144, 152),
                emphasis_text: Color32::from_rgb(20, 20, 24),
            }
        } else {
            Self {
                font,
                text: Color32::from_rgb(40, 40, 46),
                keyword: Color32::from_rgb(0, 0, 0),
                type_name: Color32::from_rgb(20, 100, 140),
                number: Color32::from_rgb(160, 80, 20),
                string: Color32::from_rgb(50, 120, 40),
                comment: Color32::from_rgb(110, 112, 120),
                emphasis_text: Color32::from_rgb(0, 0, 0),
            }
        }
    }

    /// Keywords are set in the strongest colour with an underline-free
    /// heavier look (egui has no bold monospace face, so weight is shown by
    /// colour); comments are italic.
    pub fn format(&self, class: Class) -> TextFormat {
        let mut format = TextFormat::simple(self.font.clone(), self.text);
        match class {
            Class::Plain => {}
            Class::Keyword => {
                format.color = self.keyword;
                format.font_id = FontId::new(
                    self.font.size,
                    egui::FontFamily::Name(CODE_BOLD_FAMILY.into()),
                );
            }
            Class::TypeName => format.color = self.type_name,
            Class::Number => format.color = self.number,
            Class::Text => format.color = self.string,
            Class::Comment => {
                format.color = self.comment;
                format.italics = true;
            }
        }
        format
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keywords_types_and_comments_are_classified() {
        let source = "algorithm a(v : Vertex); // hi\nbegin\n  v.mark\nend";
        let h = Highlighted::new(source);
        let class_of = |word: &str| {
            let start = source.find(word).expect("present");
            h.segments
                .iter()
                .find(|(r, _)| r.start == start)
                .map(|(_, c)| *c)
        };
        assert_eq!(class_of("algorithm"), Some(Class::Keyword));
        assert_eq!(class_of("Vertex"), Some(Class::TypeName));
        assert_eq!(class_of("// hi"), Some(Class::Comment));
        assert_eq!(class_of("mark"), Some(Class::Keyword));
        assert_eq!(class_of("v."), Some(Class::Plain));
        // The segments cover the source without gaps or overlaps.
        let mut at = 0;
        for (range, _) in &h.segments {
            assert_eq!(range.start, at);
            at = range.end;
        }
        assert_eq!(at, source.len());
    }
}
