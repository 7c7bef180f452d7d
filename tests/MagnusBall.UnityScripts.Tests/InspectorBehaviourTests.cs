using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using MagnusBall.Components;
using MagnusBall.Flight;
using MagnusBall.UnityStubs;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Events;
using static MagnusBall.UnityScripts.Tests.UnityLoop;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// What a Unity developer expects of the components beyond the flight itself: UnityEvents beside the C# events,
    /// inspector edits applied during Play (OnValidate) with a refused value reported once, gizmos, help links and
    /// inspector limits.
    /// </summary>
    [TestFixture]
    [NonParallelizable] // the stub's Time, log and gizmo records are static, as Unity's are
    public class InspectorBehaviourTests
    {
        [SetUp]
        public void Clear()
        {
            StubControl.Logged.Clear();
            StubControl.GizmoLines.Clear();
            StubControl.DeltaTime = 1f / 60f;
        }

        private static MagnusBallFlight NewFlight(SurfaceChoice surface, bool watchNet)
        {
            var holder = new GameObject("ball");
            holder.transform.position = new Vector3(-10f, 1.2f, 0.5f);
            MagnusBallFlight flight = Add<MagnusBallFlight>(holder);
            flight.settings.surface = surface;
            flight.watchPlane = watchNet;
            Call(flight, "OnValidate"); // as after an inspector edit
            return flight;
        }

        private static void Fly(MagnusBallFlight flight, int maxFrames = 100_000)
        {
            for (int frame = 0; frame < maxFrames && flight.IsFlying; frame++)
            {
                Call(flight, "Update");
            }

            Assert.That(flight.IsFlying, Is.False, "the flight ends");
        }

        [Test]
        public void TheUnityEvents_FireWithTheCSharpEvents_SameEventsSameOrder()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.Hard, watchNet: true);
            var csharp = new List<string>();
            var unity = new List<string>();
            flight.Launched += s => csharp.Add("launch");
            flight.Landed += e => csharp.Add("land " + e.Time);
            flight.Bounced += e => csharp.Add("bounce " + e.Time);
            flight.PlaneCrossed += e => csharp.Add("plane " + e.Time);
            flight.Stopped += e => csharp.Add("stop " + e.Time);
            flight.onLaunched.AddListener(() => unity.Add("launch"));
            flight.onLanded.AddListener(e => unity.Add("land " + e.Time));
            flight.onBounced.AddListener(e => unity.Add("bounce " + e.Time));
            flight.onPlaneCrossed.AddListener(e => unity.Add("plane " + e.Time));
            flight.onStopped.AddListener(e => unity.Add("stop " + e.Time));

            flight.Launch(new Vector3(24f, 6f, 1.5f), new Vector3(10f, -20f, -250f));
            Assert.That(unity, Is.EqualTo(new[] { "launch" }), "onLaunched fires inside Launch");
            Fly(flight);

            Assert.That(unity, Is.EqualTo(csharp));
            Assert.That(unity.Count(u => u.StartsWith("plane", StringComparison.Ordinal)), Is.EqualTo(1), "the net is crossed once");
            Assert.That(unity.Count(u => u.StartsWith("bounce", StringComparison.Ordinal)), Is.GreaterThanOrEqualTo(2));
            Assert.That(unity.Last(), Does.StartWith("stop"));
        }

        [Test]
        public void TheLandingUnityEvent_FiresWithoutABounceModel()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None, watchNet: false);
            var landings = new List<FlightEvent>();
            flight.onLanded.AddListener(landings.Add);
            flight.Launch(new Vector3(24f, 6f, 1.5f), Vector3.zero);
            Fly(flight);
            Assert.That(landings, Has.Count.EqualTo(1));
            Assert.That(landings[0].Kind, Is.EqualTo(FlightEventKinds.Landing));
            Assert.That(landings[0].Position.Y, Is.EqualTo(flight.Model.Ball.Radius).Within(1e-9), "the centre one radius up");
        }

        [Test]
        public void AHandlerThatCancels_StopsTheUnityEventOfTheSameEvent()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None, watchNet: false);
            int unityLandings = 0;
            flight.Landed += e => flight.Cancel();
            flight.onLanded.AddListener(e => unityLandings++);
            flight.Launch(new Vector3(24f, 6f, 1.5f), Vector3.zero);
            Fly(flight);
            Assert.That(unityLandings, Is.EqualTo(0), "the flight the C# handler cancelled raises nothing more");
        }

        [Test]
        public void AnInspectorEditDuringPlay_AppliesToTheNextLaunch_AndTheBallInFlight()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None, watchNet: false);
            var velocity = new Vector3(24f, 6f, 0f);
            flight.Launch(velocity, Vector3.zero);
            double before = flight.Model.Air.Density;
            for (int i = 0; i < 10; i++)
            {
                Call(flight, "Update");
            }

            Vector3 where = flight.transform.position;
            int arcs = flight.ArcVersion;
            flight.settings.airDensity = 0f; // edited in the inspector: no air
            Call(flight, "OnValidate");

            Assert.That(flight.Model.Air.Density, Is.EqualTo(0.0).And.Not.EqualTo(before));
            Assert.That(flight.IsFlying, Is.True, "the ball flies on");
            Assert.That(flight.ArcVersion, Is.EqualTo(arcs + 1), "a new arc from where the ball is (the preview redraws)");
            Assert.That(flight.ArcStart.Position.X, Is.EqualTo(where.x).Within(0.2), "from the ball's state, not the launch");
            Assert.That(flight.ArcStart.Velocity.X, Is.LessThan(24.0), "the velocity the drag left, not the launch's");
            Fly(flight);

            // Without air the horizontal speed no longer changes after the edit.
            FlightState end = flight.Driver!.State;
            Assert.That(end.Velocity.X, Is.EqualTo(flight.ArcStart.Velocity.X).Within(1e-12));
        }

        [Test]
        public void ARefusedInspectorEdit_IsReportedOnce_NamingTheField_AndThePreviousSettingsStay()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None, watchNet: false);
            FlightModel model = flight.Model;
            flight.settings.airDensity = -1f; // typed in (the [Min] slider stops the mouse, not the keyboard or a script)
            Call(flight, "OnValidate");
            Call(flight, "OnValidate"); // Unity calls it again at the next edit or load: no second report
            Assert.That(StubControl.Logged, Has.Count.EqualTo(1));
            Assert.That(StubControl.Logged[0], Does.StartWith("Error: MagnusBallFlight on 'ball': airDensity refused"));
            Assert.That(flight.Model, Is.SameAs(model), "the previous settings stay in use");
            Assert.DoesNotThrow(() => flight.Launch(new Vector3(24f, 6f, 0f), Vector3.zero), "and still launch");

            flight.settings.airDensity = 1.2f; // mended
            Call(flight, "OnValidate");
            Assert.That(flight.Model.Air.Density, Is.EqualTo((double)1.2f));
            flight.settings.airDensity = -1f; // broken again: reported again
            Call(flight, "OnValidate");
            Assert.That(StubControl.Logged, Has.Count.EqualTo(2));
        }

        [Test]
        public void OnValidate_LeavesACodeConfiguration_Alone()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None, watchNet: false);
            FlightModel custom = MagnusBall.Presets.SportPresets.Soccer.CreateModel(new Air(1.2), Gravity.YUp);
            flight.Configure(custom, flight.Integrator, 1.0 / 120, flight.EventSet, null);
            flight.settings.airDensity = 0.5f;
            Call(flight, "OnValidate");
            Assert.That(flight.Model, Is.SameAs(custom), "Configure's model stays until ApplySettings");
        }

        [Test]
        public void TheRigidbodyComponent_TakesAnInspectorEditDuringPlay_AndReportsARefusalOnce()
        {
            var holder = new GameObject("ball");
            holder.AddComponent<Rigidbody>();
            MagnusBallRigidbody aero = Add<MagnusBallRigidbody>(holder);
            FlightModel before = aero.Model;
            aero.settings.presetChoice = PresetChoice.Soccer;
            Call(aero, "OnValidate");
            Assert.That(aero.Model, Is.Not.SameAs(before));
            Assert.That(aero.Model.Ball.Mass, Is.EqualTo(MagnusBall.Presets.SportPresets.Soccer.Ball.Mass));
            Assert.That(holder.GetComponent<Rigidbody>().mass, Is.EqualTo((float)aero.Model.Ball.Mass), "setMass applies to the edit too");

            FlightModel soccer = aero.Model;
            aero.settings.customBall = true;
            aero.settings.radius = 0f;
            Call(aero, "OnValidate");
            Call(aero, "OnValidate");
            Assert.That(StubControl.Logged, Has.Count.EqualTo(1));
            Assert.That(StubControl.Logged[0], Does.Contain("MagnusBallRigidbody on 'ball': radius refused"));
            Assert.That(aero.Model, Is.SameAs(soccer));
        }

        [Test]
        public void Selected_TheFlightDrawsTheArcTheGroundAndTheWatchedPlane()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None, watchNet: true);
            Call(flight, "OnDrawGizmosSelected");
            Assert.That(StubControl.GizmoLines.Count(l => l.Color.Equals(Color.green)), Is.EqualTo(6), "the ground patch");
            Assert.That(StubControl.GizmoLines.Count(l => l.Color.Equals(Color.cyan)), Is.EqualTo(6), "the watched plane's patch");
            Assert.That(StubControl.GizmoLines.Any(l => l.Color.Equals(Color.yellow)), Is.False, "no arc before a launch");
            Assert.That(StubControl.GizmoLines.Where(l => l.Color.Equals(Color.green)).All(l => l.From.y == 0f && l.To.y == 0f), Is.True,
                "the ground at groundHeight (0), not at the centre's touchdown height");
            Assert.That(StubControl.GizmoLines.Where(l => l.Color.Equals(Color.cyan)).All(l => l.From.x == 0f && l.To.x == 0f), Is.True,
                "the watched plane x = 0");

            StubControl.GizmoLines.Clear();
            flight.Launch(new Vector3(24f, 6f, 1.5f), Vector3.zero);
            Call(flight, "OnDrawGizmosSelected");
            var arc = StubControl.GizmoLines.Where(l => l.Color.Equals(Color.yellow)).ToList();
            Assert.That(arc.Count, Is.GreaterThan(100), "one segment per fixed step");
            Assert.That(arc[0].From.x, Is.EqualTo(-10f), "from the launch");
            Assert.That(arc[^1].To.y, Is.EqualTo((float)flight.Model.Ball.Radius).Within(1e-4), "to the landing");
        }

        [Test]
        public void Selected_WithRefusedSettings_DrawsNothing_AndDoesNotThrow()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None, watchNet: false);
            var holder = new GameObject("other");
            MagnusBallFlight broken = holder.AddComponent<MagnusBallFlight>();
            broken.maxFrameDelta = 0f;
            Assert.DoesNotThrow(() => Call(broken, "OnDrawGizmosSelected"));
            Assert.That(StubControl.GizmoLines, Is.Empty);

            // The well-configured ball beside it still draws: the refusal is the broken one's alone.
            Call(flight, "OnDrawGizmosSelected");
            Assert.That(StubControl.GizmoLines, Is.Not.Empty);
        }

        [Test]
        public void EveryComponent_HasAHelpLink_IntoThePackagesManual()
        {
            foreach (Type component in new[] { typeof(MagnusBallFlight), typeof(MagnusBallRigidbody), typeof(MagnusBallTrajectoryPreview) })
            {
                var help = component.GetCustomAttribute<HelpURLAttribute>();
                Assert.That(help, Is.Not.Null, component.Name);
                Assert.That(help!.URL, Does.StartWith("https://github.com/magnusball/MagnusBall/blob/main/src/MagnusBall/Documentation~/MagnusBall.md#"));
                string anchor = help.URL.Substring(help.URL.IndexOf('#') + 1);
                string manual = System.IO.File.ReadAllText(System.IO.Path.Combine(RepositoryRoot(), "src", "MagnusBall", "Documentation~", "MagnusBall.md"));
                Assert.That(manual.Split('\n').Any(line => line.StartsWith("#", StringComparison.Ordinal) && Anchor(line) == anchor), Is.True,
                    $"{component.Name}: the manual has a heading for #{anchor}");
            }
        }

        // GitHub's anchor of a Markdown heading: lower case, spaces to '-', punctuation other than '-' dropped.
        private static string Anchor(string heading)
        {
            string text = heading.TrimStart('#').Trim().ToLowerInvariant();
            return new string(text.Where(c => char.IsLetterOrDigit(c) || c == ' ' || c == '-').ToArray()).Replace(' ', '-');
        }

        [TestCase(typeof(MagnusBallFlight), "fixedStep")]
        [TestCase(typeof(MagnusBallFlight), "maxFrameDelta")]
        [TestCase(typeof(MagnusBallTrajectoryPreview), "maxPoints")]
        [TestCase(typeof(MagnusBallTrajectoryPreview), "maxDuration")]
        [TestCase(typeof(FlightSettings), "mass")]
        [TestCase(typeof(FlightSettings), "radius")]
        [TestCase(typeof(FlightSettings), "airDensity")]
        [TestCase(typeof(FlightSettings), "inertiaFactor")]
        [TestCase(typeof(FlightSettings), "dragCoefficient")]
        public void NumericSettings_HaveInspectorLimits(Type type, string field)
        {
            FieldInfo info = type.GetField(field)!;
            Assert.That(info.GetCustomAttribute<MinAttribute>() != null || info.GetCustomAttribute<UnityEngine.RangeAttribute>() != null, Is.True, field);
        }

        [Test]
        public void ThePreviewRedraws_AfterAnInspectorEdit()
        {
            MagnusBallFlight flight = NewFlight(SurfaceChoice.None, watchNet: false);
            MagnusBallTrajectoryPreview preview = AddPreview(flight);
            flight.Launch(new Vector3(24f, 6f, 1.5f), Vector3.zero);
            Call(preview, "LateUpdate");
            int full = preview.PointCount;
            preview.maxDuration = 0.1f;
            Call(preview, "OnValidate");
            Call(preview, "LateUpdate");
            Assert.That(preview.Predictions, Is.EqualTo(2));
            Assert.That(preview.PointCount, Is.LessThan(full).And.GreaterThan(20), "0.1 s at 1/240 s");
        }
    }
}
