using System;
using System.Collections.Generic;
using System.Text.Json;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Shots;

namespace MagnusBall.Cli
{
    /// <summary>
    /// Reads a scenario's "shapes" (issue 40, docs/cli.md): an array of contact shapes, each an object with a "type" (box,
    /// rectangle, capsule, cylinder, sphere, torus, net-mesh, or a sport's fixture: tennis-net, soccer-goal-frame, basketball-hoop,
    /// table-tennis-net), an integer "id" (a fixture's first id) and its geometry; the primitives take "restitution",
    /// "friction" and "mass". Every field is checked with the reader's strict errors; geometry the library refuses (two equal
    /// ends, parallel axes) is an error naming the field.
    /// </summary>
    internal static class ScenarioShapes
    {
        /// <summary>The shape types a scenario accepts.</summary>
        public static readonly string[] Types =
        {
            "box", "rectangle", "capsule", "cylinder", "sphere", "torus", "net-mesh", "tennis-net", "soccer-goal-frame", "basketball-hoop", "table-tennis-net",
        };

        /// <summary>The default restitution of a primitive shape: 0.7, a game value for painted metal (SportShapes.Post carries 0.765, from the ITF rebound rule).</summary>
        public const double DefaultRestitution = 0.7;

        /// <summary>The default friction of a primitive shape: 0.3 (SportShapes.Post).</summary>
        public const double DefaultFriction = 0.3;

        /// <summary>Ids must lie within this magnitude (so a fixture's ids, first + 4 at most, cannot overflow).</summary>
        public const int MaximumId = 1_000_000_000;

        /// <summary>The shapes of a scenario's "shapes" field (empty when it is absent).</summary>
        public static IReadOnlyList<ContactShape> Read(JsonFields scenario, Vector3d up)
        {
            JsonElement? list = scenario.Optional("shapes");
            var shapes = new List<ContactShape>();
            if (!list.HasValue)
            {
                return shapes;
            }

            string path = scenario.PathOf("shapes");
            if (list.Value.ValueKind != JsonValueKind.Array)
            {
                throw new InputError(path, "must be an array of shape objects; got " + JsonFields.Describe(list.Value));
            }

            int i = 0;
            foreach (JsonElement item in list.Value.EnumerateArray())
            {
                shapes.AddRange(ReadShape(JsonFields.Of(item, $"{path}[{i}]"), up));
                i++;
            }

            return shapes;
        }

        private static IEnumerable<ContactShape> ReadShape(JsonFields f, Vector3d up)
        {
            string type = f.String("type");
            if (Array.IndexOf(Types, type) < 0)
            {
                throw new InputError(f.PathOf("type"), $"unknown shape type '{type}'; expected one of: {string.Join(", ", Types)}");
            }

            bool fixture = type == "tennis-net" || type == "soccer-goal-frame" || type == "basketball-hoop" || type == "table-tennis-net";
            int id = ReadId(f, fixture ? "firstId" : "id");
            try
            {
                ContactShape[] made = fixture ? ReadFixture(f, type, id, up) : new[] { ReadPrimitive(f, type, id) };
                f.RejectUnknown();
                return made;
            }
            catch (ArgumentException e)
            {
                // The library refused the geometry (two equal ends, parallel axes, a zero normal): name the field.
                string field = FieldOf(e.ParamName, type);
                string message = e.Message;
                int cut = message.IndexOf(" (Parameter", StringComparison.Ordinal);
                throw new InputError(f.PathOf(field), cut > 0 ? message.Substring(0, cut) : message);
            }
        }

        private static ContactShape ReadPrimitive(JsonFields f, string type, int id)
        {
            if (type == "net-mesh")
            {
                Vector3d c = f.Vector("centre"), n = f.Direction("normal"), w = f.Direction("widthDirection");
                double width = NonNegativeRequired(f, "width"), height = NonNegativeRequired(f, "height");
                double kept = f.Number("tangentialSpeedKept", 0.25);
                if (!(kept >= 0 && kept <= 1))
                {
                    throw new InputError(f.PathOf("tangentialSpeedKept"), "must be in [0, 1]; got " + JsonFields.Format(kept));
                }

                double meshMass = f.Has("mass") ? f.Positive("mass") : double.PositiveInfinity;
                return new NetMeshShape(id, c, n, w, width, height, kept, meshMass);
            }

            double restitution = f.Number("restitution", DefaultRestitution);
            if (!(restitution >= 0 && restitution <= 1))
            {
                throw new InputError(f.PathOf("restitution"), "must be in [0, 1]; got " + JsonFields.Format(restitution));
            }

            double friction = f.NonNegative("friction", DefaultFriction);
            double mass = f.Has("mass") ? f.Positive("mass") : double.PositiveInfinity;
            var contact = new ContactProperties(restitution, friction);
            switch (type)
            {
                case "box":
                {
                    Vector3d half = f.Vector("halfExtents");
                    if (!(half.X >= 0 && half.Y >= 0 && half.Z >= 0))
                    {
                        throw new InputError(f.PathOf("halfExtents"), "must have every component finite and >= 0 m; got " + JsonFields.Format(half));
                    }

                    return new BoxShape(id, f.Vector("centre"), half, f.Direction("xAxis"), f.Direction("yAxis"), contact, mass);
                }

                case "rectangle":
                    return BoxShape.Rectangle(id, f.Vector("centre"), f.Direction("normal"), f.Direction("widthDirection"),
                        NonNegativeRequired(f, "width"), NonNegativeRequired(f, "height"), contact, mass);
                case "capsule":
                    return new CapsuleShape(id, f.Vector("endA"), f.Vector("endB"), f.Positive("radius"), contact, mass);
                case "cylinder":
                    return new CylinderShape(id, f.Vector("endA"), f.Vector("endB"), f.Positive("radius"), contact, mass);
                case "sphere":
                    return new SphereShape(id, f.Vector("centre"), f.Positive("radius"), contact, mass);
                default: // torus
                    return new TorusShape(id, f.Vector("centre"), f.Direction("axis"), f.Positive("ringRadius"), f.Positive("tubeRadius"), contact, mass);
            }
        }

        private static ContactShape[] ReadFixture(JsonFields f, string type, int id, Vector3d up)
        {
            Vector3d fixtureUp = f.Has("up") ? f.Direction("up") : up;
            if (fixtureUp.LengthSquared == 0)
            {
                throw new InputError(f.PathOf("up"), "required field is missing (gravity is zero, so there is no default up)");
            }

            return type switch
            {
                "tennis-net" => SportShapes.TennisNet(id, f.Vector("centreOnGround"), f.Direction("across"), fixtureUp),
                "soccer-goal-frame" => SportShapes.SoccerGoalFrame(id, f.Vector("goalLineCentre"), f.Direction("across"), fixtureUp),
                "basketball-hoop" => SportShapes.BasketballHoop(id, f.Vector("boardFootOnGround"), f.Direction("towardCourt"), fixtureUp),
                _ => SportShapes.TableTennisNet(id, f.Vector("centreOnSurface"), f.Direction("across"), fixtureUp),
            };
        }

        private static double NonNegativeRequired(JsonFields f, string name) => f.NonNegativeRequired(name);

        private static int ReadId(JsonFields f, string name)
        {
            string path = f.PathOf(name);
            JsonElement value = f.Required(name);
            if (value.ValueKind != JsonValueKind.Number || !value.TryGetInt32(out int id) || Math.Abs((long)id) > MaximumId)
            {
                throw new InputError(path, $"must be an integer in [-{MaximumId}, {MaximumId}]; got {JsonFields.Describe(value)}");
            }

            return id;
        }

        // The JSON field a library parameter stands for.
        private static string FieldOf(string? parameter, string type) => parameter switch
        {
            "halfExtentsM" => "halfExtents",
            "widthM" => "width",
            "heightM" => "height",
            "radiusM" => "radius",
            "ringRadiusM" => "ringRadius",
            "tubeRadiusM" => "tubeRadius",
            "effectiveMassKg" => "mass",
            "first" => type == "basketball-hoop" ? "towardCourt" : "across",
            null => "type",
            _ => parameter,
        };
    }
}
