using MagnusBall.Components;
using UnityEngine;

namespace MagnusBall.Samples.TennisScene.Scripts
{
    /// <summary>
    /// Builds the sample scene from code, the same objects as Scenes/TennisScene.unity: the court (<see cref="CourtBuilder"/>),
    /// the ball (a sphere with <see cref="MagnusBallFlight"/> and <see cref="TennisBall"/>), the predicted path (a
    /// LineRenderer with <see cref="MagnusBallTrajectoryPreview"/>), the camera behind the server and the side camera, and
    /// the F1/F2 switch (<see cref="CameraSwitch"/>). Put it on an empty GameObject in a new scene (the Basic template's
    /// Directional Light lights it; its own cameras draw over the template's Main Camera) and press Play.
    /// </summary>
    public class TennisSceneBootstrap : MonoBehaviour
    {
        /// <summary>The ball's diameter, m (the tennis preset's ball: 2 x 33 mm).</summary>
        public const float BallDiameterMetres = 0.066f;

        /// <summary>The objects built (null before Awake).</summary>
        public GameObject Court { get; private set; }

        /// <summary>The ball (its TennisBall and MagnusBallFlight).</summary>
        public TennisBall Ball { get; private set; }

        /// <summary>The predicted path.</summary>
        public MagnusBallTrajectoryPreview Preview { get; private set; }

        /// <summary>The F1/F2 camera switch, with both cameras.</summary>
        public CameraSwitch Cameras { get; private set; }

        private void Awake()
        {
            Court = new GameObject("Tennis Court");
            Court.AddComponent<CourtBuilder>(); // builds at Start

            GameObject ball = GameObject.CreatePrimitive(PrimitiveType.Sphere);
            ball.name = "Ball";
            ball.transform.localScale = new Vector3(BallDiameterMetres, BallDiameterMetres, BallDiameterMetres);
            ball.AddComponent<RuntimeMaterial>().color = new Color(0.85f, 0.95f, 0.2f, 1f);
            MagnusBallFlight flight = ball.AddComponent<MagnusBallFlight>();
            Ball = ball.AddComponent<TennisBall>();
            ball.transform.position = Ball.servePosition; // it serves from here at Start

            var path = new GameObject("Predicted Path");
            LineRenderer line = path.AddComponent<LineRenderer>(); // before the preview, which takes it at Awake
            line.widthMultiplier = 0.02f;
            path.AddComponent<RuntimeMaterial>().color = new Color(1f, 0.85f, 0.1f, 1f);
            Preview = path.AddComponent<MagnusBallTrajectoryPreview>();
            Preview.flight = flight;

            // Unity's Euler order (z, then x, then y): yaw * pitch.
            Camera primary = NewCamera("Server Camera", new Vector3(-16f, 4f, 0f), yawDegrees: 90f, pitchDegrees: 10f);
            Camera secondary = NewCamera("Side Camera", new Vector3(0f, 3f, -16f), yawDegrees: 0f, pitchDegrees: 5f);
            Cameras = new GameObject("Camera Switch").AddComponent<CameraSwitch>();
            Cameras.primaryCamera = primary;
            Cameras.secondaryCamera = secondary;
        }

        private static Camera NewCamera(string name, Vector3 position, float yawDegrees, float pitchDegrees)
        {
            var holder = new GameObject(name);
            holder.transform.position = position;
            holder.transform.rotation = Quaternion.AngleAxis(yawDegrees, new Vector3(0f, 1f, 0f)) * Quaternion.AngleAxis(pitchDegrees, new Vector3(1f, 0f, 0f));
            Camera camera = holder.AddComponent<Camera>();
            camera.depth = 1; // above a template's Main Camera (depth -1)
            return camera;
        }
    }
}
