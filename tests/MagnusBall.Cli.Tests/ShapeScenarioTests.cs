using System;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Xml.Linq;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests
{
    /// <summary>
    /// Issue 40, item 6a: the scenario schema takes contact shapes (with the same strict errors as every field), the JSON
    /// output reports the contacts, and the SVG draws the shapes.
    /// </summary>
    [TestFixture]
    public class ShapeScenarioTests
    {
        // The drive, low enough to hit the tennis net, with the net as shapes (ids 0-4) and a wall behind the far baseline.
        private static JsonObject IntoTheNet(string shapesJson)
        {
            JsonObject root = CliRun.Drive();
            JsonObject s = CliRun.FirstScenario(root);
            s["initial"]!["velocity"] = JsonNode.Parse("[29.7, 0, 2]");
            s["shapes"] = JsonNode.Parse(shapesJson);
            return root;
        }

        private const string Net = """[{"type": "tennis-net", "firstId": 0, "centreOnGround": [11.885, 0, 0], "across": [0, 1, 0]}]""";

        [Test]
        public void ATennisNet_StopsALowDrive_AndTheContactIsInTheOutput()
        {
            CliRun run = CliRun.Simulate(IntoTheNet(Net));
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            JsonElement result = run.FirstResult();
            JsonElement contacts = result.GetProperty("contacts");
            Assert.That(contacts.GetArrayLength(), Is.GreaterThanOrEqualTo(1));
            JsonElement first = contacts[0];
            Assert.That(first.GetProperty("shapeId").GetInt32(), Is.EqualTo(2), "the mesh");
            Assert.That(first.GetProperty("position")[0].GetDouble(), Is.EqualTo(11.885 - 0.033).Within(1e-6), "the ball's surface touches the mesh");
            Assert.That(first.GetProperty("normal")[0].GetDouble(), Is.EqualTo(-1).Within(1e-9));
            Assert.That(Math.Abs(first.GetProperty("velocityAfter")[0].GetDouble()), Is.LessThan(5), "the mesh takes most of its speed");
            Assert.That(result.GetProperty("landing").GetProperty("position")[0].GetDouble(), Is.LessThan(11.885), "it drops on the near side");
        }

        [Test]
        public void Primitives_AreRead_AndAScenarioWithoutShapes_HasNoContactsField()
        {
            const string shapes = """
                [{"type": "box", "id": 7, "centre": [30, 0, 1], "halfExtents": [0.1, 5, 1], "xAxis": [1, 0, 0], "yAxis": [0, 1, 0], "restitution": 0.5, "friction": 0.2},
                 {"type": "rectangle", "id": 8, "centre": [40, 0, 1], "normal": [-1, 0, 0], "widthDirection": [0, 1, 0], "width": 2, "height": 2, "mass": 5},
                 {"type": "capsule", "id": 9, "endA": [50, -1, 1], "endB": [50, 1, 1], "radius": 0.05},
                 {"type": "cylinder", "id": 10, "endA": [60, 0, 0], "endB": [60, 0, 2], "radius": 0.05},
                 {"type": "sphere", "id": 13, "centre": [65, 0, 1], "radius": 0.2, "mass": 0.4},
                 {"type": "torus", "id": 11, "centre": [70, 0, 3], "axis": [0, 0, 1], "ringRadius": 0.23, "tubeRadius": 0.01},
                 {"type": "net-mesh", "id": 12, "centre": [80, 0, 0.5], "normal": [1, 0, 0], "widthDirection": [0, 1, 0], "width": 10, "height": 1, "tangentialSpeedKept": 0.3},
                 {"type": "soccer-goal-frame", "firstId": 20, "goalLineCentre": [90, 0, 0], "across": [0, 1, 0]},
                 {"type": "basketball-hoop", "firstId": 30, "boardFootOnGround": [100, 0, 0], "towardCourt": [-1, 0, 0], "up": [0, 0, 1]},
                 {"type": "table-tennis-net", "firstId": 40, "centreOnSurface": [110, 0, 0], "across": [0, 1, 0]}]
                """;
            CliRun run = CliRun.Simulate(IntoTheNet(shapes));
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            Assert.That(run.FirstResult().GetProperty("contacts").GetArrayLength(), Is.EqualTo(0), "nothing in the way of this short flight");

            CliRun plain = CliRun.Simulate(CliRun.DriveJson);
            Assert.That(plain.FirstResult().TryGetProperty("contacts", out _), Is.False);
        }

        [TestCase("""[{"type": "capsule", "id": 1, "endA": [1, 0, 1], "endB": [1, 0, 1], "radius": 0.1}]""", "scenarios[0].shapes[0].endB: endB must lie between 1e-150 m")]
        [TestCase("""[{"type": "capsule", "id": 1, "endA": [1, 0, 1], "endB": [1, 1, 1], "radius": -0.1}]""", "scenarios[0].shapes[0].radius: must be finite and > 0; got -0.1")]
        [TestCase("""[{"type": "capsule", "id": 1, "endA": [1, 0, 1], "endB": [1, 1, 1], "radius": 0.1, "radus": 1}]""", "scenarios[0].shapes[0].radus: unknown field; expected one of:")]
        [TestCase("""[{"type": "cone", "id": 1}]""", "scenarios[0].shapes[0].type: unknown shape type 'cone'; expected one of: box, rectangle, capsule")]
        [TestCase("""[{"type": "sphere", "id": 1, "centre": [1, 0, 1], "radius": 0}]""", "scenarios[0].shapes[0].radius: must be finite and > 0; got 0")]
        [TestCase("""[{"type": "torus", "id": 1.5, "centre": [0, 0, 3], "axis": [0, 0, 1], "ringRadius": 0.2, "tubeRadius": 0.01}]""", "scenarios[0].shapes[0].id: must be an integer in [-1000000000, 1000000000]; got 1.5")]
        [TestCase("""[{"type": "box", "id": 1, "centre": [0, 0, 3], "halfExtents": [1, -1, 1], "xAxis": [1, 0, 0], "yAxis": [0, 1, 0]}]""", "scenarios[0].shapes[0].halfExtents: must have every component finite and >= 0 m")]
        [TestCase("""[{"type": "box", "id": 1, "centre": [0, 0, 3], "halfExtents": [1, 1, 1], "xAxis": [1, 0, 0], "yAxis": [2, 0, 0]}]""", "scenarios[0].shapes[0].yAxis: yAxis must not be parallel to xAxis")]
        [TestCase("""[{"type": "rectangle", "id": 1, "centre": [0, 0, 3], "normal": [0, 0, 0], "widthDirection": [0, 1, 0], "width": 1, "height": 1}]""", "scenarios[0].shapes[0].normal: must be a non-zero direction")]
        [TestCase("""[{"type": "cylinder", "id": 1, "endA": [1, 0, 0], "endB": [1, 0, 1], "radius": 0.1, "restitution": 1.5}]""", "scenarios[0].shapes[0].restitution: must be in [0, 1]; got 1.5")]
        [TestCase("""[{"type": "cylinder", "id": 1, "endA": [1, 0, 0], "endB": [1, 0, 1], "radius": 0.1, "mass": 0}]""", "scenarios[0].shapes[0].mass: must be finite and > 0; got 0")]
        [TestCase("""[{"type": "net-mesh", "id": 1, "centre": [1, 0, 0], "normal": [1, 0, 0], "widthDirection": [0, 1, 0], "width": 1, "height": 1, "tangentialSpeedKept": 2}]""", "scenarios[0].shapes[0].tangentialSpeedKept: must be in [0, 1]; got 2")]
        [TestCase("""[{"type": "tennis-net", "firstId": 0, "centreOnGround": [11.885, 0, 0], "across": [0, 0, 1]}]""", "scenarios[0].shapes[0].up: up must not be along the first direction")]
        [TestCase("""{"type": "box"}""", "scenarios[0].shapes: must be an array of shape objects; got an object")]
        [TestCase("""[3]""", "scenarios[0].shapes[0]: must be an object; got 3")]
        public void ABadShape_ExitsWith2_AndOneLineNamingItsPath(string shapes, string expected)
        {
            CliRun run = CliRun.Simulate(IntoTheNet(shapes));
            Assert.That(run.ExitCode, Is.EqualTo(2), run.Stdout);
            Assert.That(run.Stdout, Is.Empty);
            Assert.That(run.Stderr, Does.Contain(expected));
            Assert.That(run.Stderr.Trim().Split('\n'), Has.Length.EqualTo(1), run.Stderr);
        }

        [Test]
        public void TheSvg_DrawsTheShapes_AndMarksTheContact()
        {
            string path = Path.Combine(Path.GetTempPath(), $"magnusball-{Guid.NewGuid():N}.svg");
            try
            {
                const string shapes = """
                    [{"type": "tennis-net", "firstId": 0, "centreOnGround": [11.885, 0, 0], "across": [0, 1, 0]},
                     {"type": "box", "id": 7, "centre": [20, 0, 1], "halfExtents": [0.2, 1, 1], "xAxis": [1, 0, 0], "yAxis": [0, 1, 0]},
                     {"type": "torus", "id": 11, "centre": [15, 0, 3], "axis": [0, 0, 1], "ringRadius": 0.23, "tubeRadius": 0.01}]
                    """;
                CliRun run = CliRun.Simulate(IntoTheNet(shapes), "--svg", path);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
                XNamespace ns = "http://www.w3.org/2000/svg";
                XDocument svg = XDocument.Load(path);
                var grey = svg.Descendants().Where(e => (string?)e.Attribute("fill") == "#777777" || (string?)e.Attribute("stroke") == "#777777").ToList();
                // Side view: the cords as two circles (their axis out of the view), the mesh and the box as rectangles, the
                // posts as thick lines, the torus as its two tube circles; the top view: the cords and posts, the mesh, box, ring.
                // The tennis net's mesh is 2 x SportShapes.TennisMeshPiecesPerHalf rectangles (following its sagging cord).
                int meshPieces = 2 * MagnusBall.Shots.SportShapes.TennisMeshPiecesPerHalf;
                Assert.That(grey.Count(e => e.Name == ns + "polygon"), Is.EqualTo(2 * (meshPieces + 1)), "the mesh's pieces and the box, in each view");
                Assert.That(grey.Count(e => e.Name == ns + "ellipse"), Is.GreaterThanOrEqualTo(4));
                Assert.That(grey.Count(e => e.Name == ns + "line"), Is.GreaterThanOrEqualTo(4));
                Assert.That(svg.Descendants(ns + "polygon").Count(e => (string?)e.Attribute("fill") == "white"), Is.GreaterThanOrEqualTo(2), "the contact's diamond in each view");
                Assert.That(File.ReadAllText(path), Does.Contain("diamond: contact with a shape"));
            }
            finally
            {
                File.Delete(path);
            }
        }

        [Test]
        public void TheSvg_DrawsARotatedBox_AsItsOutline_NotItsBoundingBox()
        {
            // A cube turned 45 degrees about the vertical: from above it is a diamond, each corner at the middle of the
            // outline's extent along one axis (the bounding box would put every corner at a corner of the extent).
            string path = Path.Combine(Path.GetTempPath(), $"magnusball-{Guid.NewGuid():N}.svg");
            try
            {
                const string shapes = """
                    [{"type": "box", "id": 7, "centre": [15, 0, 1], "halfExtents": [0.5, 0.5, 0.5], "xAxis": [1, 1, 0], "yAxis": [-1, 1, 0]}]
                    """;
                CliRun run = CliRun.Simulate(IntoTheNet(shapes), "--svg", path);
                Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
                XNamespace ns = "http://www.w3.org/2000/svg";
                var outlines = XDocument.Load(path).Descendants(ns + "polygon")
                    .Where(e => (string?)e.Attribute("fill") == "#777777")
                    .Select(e => ((string)e.Attribute("points")!).Split(' ').Select(p => p.Split(',').Select(v => double.Parse(v, System.Globalization.CultureInfo.InvariantCulture)).ToArray()).ToList())
                    .ToList();
                Assert.That(outlines, Has.Count.EqualTo(2), "one outline in each view");
                bool diamond = outlines.Any(o =>
                {
                    double midX = 0.5 * (o.Min(p => p[0]) + o.Max(p => p[0])), midY = 0.5 * (o.Min(p => p[1]) + o.Max(p => p[1]));
                    return o.Count == 4 && o.Count(p => Math.Abs(p[0] - midX) < 0.5 || Math.Abs(p[1] - midY) < 0.5) == 4;
                });
                Assert.That(diamond, Is.True, "the top view's outline is the turned square");
            }
            finally
            {
                File.Delete(path);
            }
        }

        [Test]
        public void ASphere_IsHit_WhereTheSurfacesTouch()
        {
            // A 0.2 m sphere centred 1.1 m up at x = 8 m, across the drive's path: the ball's surface touches it.
            CliRun run = CliRun.Simulate(IntoTheNet("""[{"type": "sphere", "id": 5, "centre": [8, 0, 1.1], "radius": 0.2}]"""));
            Assert.That(run.ExitCode, Is.EqualTo(0), run.Stderr);
            JsonElement first = run.FirstResult().GetProperty("contacts")[0];
            Assert.That(first.GetProperty("shapeId").GetInt32(), Is.EqualTo(5));
            double[] p = first.GetProperty("position").EnumerateArray().Select(v => v.GetDouble()).ToArray();
            double distance = Math.Sqrt((p[0] - 8) * (p[0] - 8) + p[1] * p[1] + (p[2] - 1.1) * (p[2] - 1.1));
            Assert.That(distance, Is.EqualTo(0.2 + 0.033).Within(1e-9));
        }
    }
}
