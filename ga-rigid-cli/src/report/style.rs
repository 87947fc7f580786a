//! How each method looks in the report: the panel of the work-precision diagram it is
//! drawn in, and a colour and marker that are its own wherever it appears.
//!
//! A diagram of 30 methods in one frame cannot be read, so each scene's diagram is five
//! small panels of at most eight lines: our second-order steppers, our fixed-step methods
//! of order four and up, our adaptive, multistep (Adams) and exact methods, the engines' steps among the
//! peers and the other peers, each peer panel with our fastest method repeated beside it. Within a panel every method has its own colour (the
//! eight colours of Okabe and Ito's palette, which stay apart for colour-blind readers);
//! each panel has its own marker, so a method's colour and marker together name it in
//! every diagram. Peers are drawn dashed, in the plot and in the legend.

use plotters::style::RGBColor;

use ga_rigid::registry::Method;

/// A panel of a scene's work-precision diagram: a family of methods.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Panel {
    /// Our second-order fixed-step methods.
    SecondOrder,
    /// Our fixed-step methods of order four and higher.
    HighOrder,
    /// Our adaptive methods, the Adams-Bashforth-Moulton methods (fixed step, but the
    /// panel of order four and up holds eight already), the exact flow and the closed form.
    AdaptiveAndExact,
    /// The engines' steps among the peers (and, drawn beside them, our fastest).
    EnginePeers,
    /// The other methods people use today (and, drawn beside them, our fastest).
    Peers,
}

impl Panel {
    /// The five panels in the order they are drawn (left to right, top to bottom).
    pub const ALL: [Panel; 5] = [
        Panel::SecondOrder,
        Panel::HighOrder,
        Panel::AdaptiveAndExact,
        Panel::EnginePeers,
        Panel::Peers,
    ];

    /// Whether the panel holds peers.
    #[must_use]
    pub fn is_peers(self) -> bool {
        matches!(self, Panel::EnginePeers | Panel::Peers)
    }

    /// The panel's title.
    #[must_use]
    pub fn title(self) -> &'static str {
        match self {
            Panel::SecondOrder => "ours: second-order steppers",
            Panel::HighOrder => "ours: fixed step, order 4 and up",
            Panel::AdaptiveAndExact => "ours: adaptive, Adams, exact, closed form",
            Panel::EnginePeers => "engine steps (dashed) and our fastest to the best peer",
            Panel::Peers => "other peers (dashed) and our fastest to the best peer",
        }
    }

    /// The panel's marker.
    #[must_use]
    pub fn marker(self) -> Marker {
        match self {
            Panel::SecondOrder => Marker::Circle,
            Panel::HighOrder => Marker::Square,
            Panel::AdaptiveAndExact => Marker::Triangle,
            Panel::EnginePeers => Marker::OpenSquare,
            Panel::Peers => Marker::Ring,
        }
    }

    /// The methods of this panel, in the registry's order.
    #[must_use]
    pub fn methods(self) -> Vec<Method> {
        Method::ALL
            .iter()
            .copied()
            .filter(|&m| panel(m) == self)
            .collect()
    }
}

/// A point's marker.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Marker {
    /// A filled circle.
    Circle,
    /// A filled square.
    Square,
    /// A filled triangle, point up.
    Triangle,
    /// An open circle.
    Ring,
    /// An open square.
    OpenSquare,
}

/// How one method is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Style {
    /// Its colour.
    pub colour: RGBColor,
    /// Its marker.
    pub marker: Marker,
    /// Whether its line is dashed (the peers').
    pub dashed: bool,
}

/// Okabe and Ito's eight colours (Color Universal Design, 2002), with their yellow
/// darkened so that it reads on white.
pub(crate) const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 0, 0),       // black
    RGBColor(230, 159, 0),   // orange
    RGBColor(86, 180, 233),  // sky blue
    RGBColor(0, 158, 115),   // bluish green
    RGBColor(190, 170, 0),   // yellow, darkened
    RGBColor(0, 114, 178),   // blue
    RGBColor(213, 94, 0),    // vermilion
    RGBColor(204, 121, 167), // reddish purple
];

/// The panel a method is drawn in.
#[must_use]
pub fn panel(method: Method) -> Panel {
    use Method::*;
    if method.info().peer.is_some() {
        return match method {
            EulerGyroExplicit | EulerGyroImplicit | Buss2 | SpiersVelocity | SpiersMomentum => {
                Panel::EnginePeers
            }
            _ => Panel::Peers,
        };
    }
    match method {
        Midpoint | Splitting | SplittingCayley | SplittingCasimir | SplittingCorrected
        | ExactSplitting => Panel::SecondOrder,
        Rk4 | LieRk4 | Splitting4 | Splitting6 | Splitting8 | ExactSplitting4 | ExactSplitting6
        | ExactSplitting8 => Panel::HighOrder,
        // Eight colours to a panel: the high-order panel is full.
        Adams10 | Adams12 => Panel::AdaptiveAndExact,
        _ => Panel::AdaptiveAndExact,
    }
}

/// The method's colour and marker: its panel's marker, and the colour of its place among
/// its panel's methods, so that no two methods of a panel share a colour.
#[must_use]
pub fn style(method: Method) -> Style {
    let home = panel(method);
    let place = home
        .methods()
        .iter()
        .position(|&m| m == method)
        .unwrap_or(0);
    Style {
        colour: PALETTE[place % PALETTE.len()],
        marker: home.marker(),
        dashed: home.is_peers(),
    }
}

/// The method's colour (its [`style`]'s), for the page's tables.
#[must_use]
pub fn method_colour(method: Method) -> RGBColor {
    style(method).colour
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 32's complaint was five colours used twice in one frame: now no panel holds
    /// more than eight methods, no two of a panel share a colour, and every method's
    /// colour and marker together are its own.
    #[test]
    fn every_method_has_its_own_colour_and_marker_and_no_panel_is_crowded() {
        for panel in Panel::ALL {
            let methods = panel.methods();
            assert!((1..=8).contains(&methods.len()), "{panel:?}: {methods:?}");
            let mut colours: Vec<_> = methods.iter().map(|&m| style(m).colour).collect();
            colours.dedup();
            colours.sort_by_key(|c| (c.0, c.1, c.2));
            colours.dedup();
            assert_eq!(colours.len(), methods.len(), "{panel:?}");
        }
        for (k, &a) in Method::ALL.iter().enumerate() {
            for &b in &Method::ALL[k + 1..] {
                let (sa, sb) = (style(a), style(b));
                assert!(
                    (sa.colour, sa.marker) != (sb.colour, sb.marker),
                    "{a:?} and {b:?} look alike"
                );
            }
        }
        assert!(style(Method::Dop853Quaternion).dashed);
        assert!(!style(Method::LieDop853).dashed);
    }
}
