using UnityEngine;

namespace MagnusBall.Samples.TennisScene.Scripts
{
    /// <summary>
    /// Two cameras, as in the thesis's scene (Agrawal 2023, section 3.2): F1 shows the secondary camera,
    /// F2 the primary one. Keys are read through <see cref="SceneInput"/> (Input System or Input Manager).
    /// </summary>
    public class CameraSwitch : MonoBehaviour
    {
        [Tooltip("Behind the hitter, looking down +x (the thesis's main view).")]
        public Camera primaryCamera;
        [Tooltip("Side-on, to see the curve of the flight.")]
        public Camera secondaryCamera;
        public KeyCode secondaryKey = KeyCode.F1;
        public KeyCode primaryKey = KeyCode.F2;

        private void Start() => Show(primary: true);

        private void Update()
        {
            if (SceneInput.WasPressed(secondaryKey))
            {
                Show(primary: false);
            }
            else if (SceneInput.WasPressed(primaryKey))
            {
                Show(primary: true);
            }
        }

        /// <summary>Enables one camera and disables the other.</summary>
        /// <param name="primary">True for the primary camera.</param>
        public void Show(bool primary)
        {
            if (primaryCamera != null)
            {
                primaryCamera.enabled = primary;
            }

            if (secondaryCamera != null)
            {
                secondaryCamera.enabled = !primary;
            }
        }
    }
}
