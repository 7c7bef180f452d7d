using System.Linq;
using System.Text.Json.Nodes;
using MagnusBall.Aerodynamics;
using NUnit.Framework;

namespace MagnusBall.Cli.Tests
{
    /// <summary>Each model name in a scenario builds the library's law with the given parameter.</summary>
    [TestFixture]
    public class ModelBuildingTests
    {
        private static Scenario Read(System.Action<JsonObject> mutate)
        {
            JsonObject root = CliRun.Drive();
            mutate(CliRun.FirstScenario(root));
            return ScenarioReader.Read(root.ToJsonString()).Single();
        }

        [Test]
        public void DragModels()
        {
            Assert.That(((ConstantDrag)Read(s => { })!.Model.Drag!).Value, Is.EqualTo(0.55));
            Assert.That(Read(s => s["aero"]!["drag"] = JsonNode.Parse("{\"model\": \"stepanek\"}")).Model.Drag, Is.SameAs(StepanekDrag.Instance));
            Assert.That(Read(s => s["aero"]!["drag"] = JsonNode.Parse("{\"model\": \"none\"}")).Model.Drag, Is.Null);
            Assert.That(Read(s => s["aero"]!.AsObject().Remove("drag")).Model.Drag, Is.Null);
        }

        [Test]
        public void LiftModels()
        {
            Assert.That(((ConstantLift)Read(s => { }).Model.Lift!).Value, Is.EqualTo(0.175));
            Assert.That(Read(s => s["aero"]!["lift"] = JsonNode.Parse("{\"model\": \"stepanek\"}")).Model.Lift, Is.SameAs(StepanekLift.Instance));
            Assert.That(((LinearSpinLift)Read(s => s["aero"]!["lift"] = JsonNode.Parse("{\"model\": \"linear-spin\", \"k\": 0.6}")).Model.Lift!).Slope, Is.EqualTo(0.6));
            Assert.That(Read(s => s["aero"]!["lift"] = JsonNode.Parse("{\"model\": \"none\"}")).Model.Lift, Is.Null);
        }

        [Test]
        public void PublishedLawsOfOtherSports()
        {
            Assert.That(Read(s => s["aero"]!["drag"] = JsonNode.Parse("{\"model\": \"goff-carre\"}")).Model.Drag, Is.SameAs(GoffCarreSoccerDrag.Instance));
            Assert.That(Read(s => s["aero"]!["lift"] = JsonNode.Parse("{\"model\": \"goff-carre\"}")).Model.Lift, Is.SameAs(PiecewiseLinearLift.SoccerGoffCarre));
            Assert.That(Read(s => s["aero"]!["drag"] = JsonNode.Parse("{\"model\": \"nathan\"}")).Model.Drag, Is.SameAs(NathanBaseballDrag.Instance));
            Assert.That(Read(s => s["aero"]!["lift"] = JsonNode.Parse("{\"model\": \"Nathan\"}")).Model.Lift, Is.SameAs(NathanBaseballLift.Instance), "model names ignore case");
            var drag = (LinearSpinDrag)Read(s => s["aero"]!["drag"] = JsonNode.Parse("{\"model\": \"linear-spin\", \"cd0\": 0.24, \"k\": 0.18}")).Model.Drag!;
            Assert.That(((IDragModel)drag).DragCoefficient(new AeroConditions(10, 0, 0, 0.02, 1.2, 1.8e-5)), Is.EqualTo(0.24));
        }

        [Test]
        public void Integrators_IncludeTheDormandPrincePair()
        {
            Assert.That(Read(s => s["integrator"] = "dp54").Integrator, Is.SameAs(MagnusBall.Integration.DormandPrince54.Instance));
            Assert.That(Read(s => s["integrator"] = "heun").Integrator, Is.SameAs(MagnusBall.Integration.Heun.Instance));
        }

        [Test]
        public void SpinDecayModels()
        {
            Assert.That(Read(s => { }).Model.SpinDecay, Is.Null);
            var decay = (ExponentialSpinDecay)Read(s => s["spinDecay"] = JsonNode.Parse("{\"model\": \"exponential\", \"tau\": 2.5}")).Model.SpinDecay!;
            Assert.That(decay.TimeConstant, Is.EqualTo(2.5));
            var perMetre = (SpeedProportionalSpinDecay)Read(s => s["spinDecay"] = JsonNode.Parse("{\"model\": \"speed-proportional\", \"k\": 0.003}")).Model.SpinDecay!;
            Assert.That(((ISpinDecayModel)perMetre).SpinAcceleration(new Vector3d(0, 100, 0), new AeroConditions(20, 100, 100, 0.033, 1.2, 1.8e-5)).Y, Is.EqualTo(-0.003 * 20 * 100).Within(1e-12));
        }

        [Test]
        public void BallAirAndInitialState()
        {
            Scenario s = Read(x =>
            {
                x["ball"]!["inertiaFactor"] = 0.55;
                x["air"]!["wind"] = new JsonArray(1, 2, 3);
                x["initial"]!["time"] = 5;
            });
            Assert.Multiple(() =>
            {
                Assert.That(s.Model.Ball.Mass, Is.EqualTo(0.057));
                Assert.That(s.Model.Ball.Radius, Is.EqualTo(0.033));
                Assert.That(s.Model.Ball.InertiaFactor, Is.EqualTo(0.55));
                Assert.That(s.Model.Air.Density, Is.EqualTo(1.21));
                Assert.That(s.Model.Air.Wind, Is.EqualTo(new Vector3d(1, 2, 3)));
                Assert.That(s.Initial.AngularVelocity, Is.EqualTo(new Vector3d(0, 125.7, 0)));
                Assert.That(s.Initial.Time, Is.EqualTo(5));
                Assert.That(s.Planes.Single().Normal, Is.EqualTo(new Vector3d(1, 0, 0)));
            });
        }

        [Test]
        public void PlaneNormals_AreNormalised()
        {
            Scenario s = Read(x => x["planes"]![0]!["normal"] = new JsonArray(3, 0, 4));
            Assert.That(s.Planes[0].Normal.Length, Is.EqualTo(1).Within(1e-15));
        }
    }
}
